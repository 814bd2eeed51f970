// Advisory lock of an output directory (see output_lock.hpp): flock(2) on DIR/.lrchain-lock.
#include "lrchain/jobs/output_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>

#include "lrchain/errors.hpp"

namespace lrchain::jobs {

namespace fs = std::filesystem;

namespace {

constexpr const char* lock_name = ".lrchain-lock";

// The pid written in a lock file ("" if unreadable).
std::string holder_pid(int fd) {
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  std::string s = n > 0 ? std::string(buf, std::size_t(n)) : "";
  while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
  return s;
}

}  // namespace

OutputLock::OutputLock(const fs::path& dir) : dir_(dir) {
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw InputError("--out '" + dir.string() + "' exists and is not a directory");
  for (fs::path p = dir; !p.empty() && !fs::exists(p, ec); p = p.parent_path()) {
    created_.push_back(p);
    if (p == p.parent_path()) break;
  }
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
    throw InputError("cannot create the output directory '" + dir.string() + "': " + ec.message());
  const fs::path file = dir / lock_name;
  // Retry if the file was removed and re-created between open and flock (its holder finished).
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw InputError("cannot create '" + file.string() + "': " + std::strerror(errno));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const std::string pid = holder_pid(fd);
      ::close(fd);
      throw InputError("--out '" + dir.string() + "' is in use by another lrchain run (pid " +
                       (pid.empty() ? "unknown" : pid) + "); wait for it or choose another directory");
    }
    struct stat held{}, now{};
    if (::fstat(fd, &held) == 0 && ::stat(file.c_str(), &now) == 0 && held.st_ino == now.st_ino &&
        held.st_dev == now.st_dev) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, pid.data(), pid.size(), 0) != ssize_t(pid.size())) {
        // The lock holds without the pid; the message of a second run then says "unknown".
      }
      fd_ = fd;
      return;
    }
    ::close(fd);
  }
  throw InputError("cannot lock the output directory '" + dir.string() + "'");
}

void OutputLock::moved_to(const fs::path& dir) { dir_ = dir; created_.clear(); }

OutputLock::~OutputLock() {
  if (fd_ < 0) return;
  std::error_code ec;
  fs::remove(dir_ / lock_name, ec);  // unlink while still holding it, so no one locks a stale file
  ::close(fd_);
  for (const auto& d : created_) fs::remove(d, ec);  // removes only empty directories
}

}  // namespace lrchain::jobs
