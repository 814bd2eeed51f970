#pragma once
// The one decision every writer of lrchain makes before it writes a file (CSV, binary, HDF5,
// checkpoint, figure, summary, report page): may this path be replaced? Writers put their bytes
// under a temporary name and rename it over the target; renaming over a device, FIFO, socket or
// directory would replace a system object (run as root, /dev/null became a regular file), so such
// a target is refused before anything is written.
#include <filesystem>

namespace lrchain {

// Throws InputError naming `target` when it exists (following symbolic links) and is not a
// regular file: a character or block device, a FIFO, a socket or a directory ("'/dev/null' is a
// character device, not a regular file: lrchain writes regular files only"). A missing target, a
// regular file, or a dangling symbolic link (replaced by the rename) may be written.
void check_output_target(const std::filesystem::path& target);

}  // namespace lrchain
