// May a writer replace this path (output_target.hpp): only a missing path or a regular file.
#include "lrchain/output_target.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <string>

#include "lrchain/errors.hpp"
#include "file_kind.hpp"

namespace lrchain {

void check_output_target(const std::filesystem::path& target) {
  struct stat st {};
  if (::stat(target.c_str(), &st) != 0) {
    if (errno == ENOENT) return;  // missing, or a dangling symbolic link: the rename creates the file
    if (errno == ENOTDIR)
      throw InputError("'" + target.string() + "': a component of its directory is not a directory");
    return;  // (permissions and the like: the write itself reports them)
  }
  if (S_ISREG(st.st_mode)) return;
  throw InputError("'" + target.string() + "' is " + file_kind_text(st.st_mode) +
                   ", not a regular file: lrchain writes regular files only and never replaces it");
}

}  // namespace lrchain
