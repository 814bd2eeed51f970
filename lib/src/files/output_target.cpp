// May a writer replace this path (output_target.hpp): only a missing path or a regular file.
#include "lrchain/output_target.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <string>

#include "lrchain/errors.hpp"

namespace lrchain {

namespace {

// What a non-regular file is, for the message.
const char* kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

void check_output_target(const std::filesystem::path& target) {
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0) {
    if (errno == ENOENT) return;  // missing, or a dangling symbolic link: the rename creates the file
    if (errno == ENOTDIR)
      throw InputError("'" + target.string() + "': a component of its directory is not a directory");
    return;  // (permissions and the like: the write itself reports them)
  }
  if (S_ISREG(st.st_mode)) return;
  throw InputError("'" + target.string() + "' is " + kind_of(st.st_mode) +
                   ", not a regular file: lrchain writes regular files only and never replaces it");
}

}  // namespace lrchain
