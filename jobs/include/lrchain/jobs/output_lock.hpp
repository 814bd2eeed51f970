#pragma once
// One run per output directory: an advisory lock (flock) on DIR/.lrchain-lock, which records the
// holder's pid. A second run into the same directory is refused with exit 2 naming that pid.
#include <filesystem>
#include <vector>

namespace lrchain::jobs {

class OutputLock {
 public:
  // Creates dir (and missing parents) and takes the lock. Throws lrchain::InputError (exit 2) if
  // dir exists and is not a directory, cannot be created, or another process holds the lock.
  // Take it after the input is validated: it is the job's first write into dir.
  explicit OutputLock(const std::filesystem::path& dir);
  // Removes the lock file, then the directories this lock created if they are still empty.
  ~OutputLock();
  OutputLock(const OutputLock&) = delete;
  OutputLock& operator=(const OutputLock&) = delete;
  // The directory was renamed (e.g. DIR.partial -> DIR) while locked: release the lock there.
  void moved_to(const std::filesystem::path& dir);

 private:
  std::filesystem::path dir_;
  std::vector<std::filesystem::path> created_;  // deepest first
  int fd_ = -1;
};

}  // namespace lrchain::jobs
