#pragma once
// What a file that is not a regular file is, in words, for messages that refuse it (writers'
// targets, model files): "a directory", "a character device", "a FIFO (named pipe)", ...
#include <sys/types.h>

namespace lrchain {

// The kind of the file with st_mode `mode`; "not a regular file" for a kind not listed.
const char* file_kind_text(mode_t mode);

}  // namespace lrchain
