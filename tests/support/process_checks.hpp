#pragma once
// Checks on processes for tests of stopping children: waiting for a pid a script writes, and
// whether a process is gone (killed: exited, or a zombie waiting for init to reap it).
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <string>

namespace lrchain::test {

// The pid in `pid_file` once it exists (written by a script, renamed into place), 0 after `seconds`.
inline pid_t wait_for_pid_file(const std::filesystem::path& pid_file, double seconds) {
  for (int i = 0; i < int(seconds * 50) && !std::filesystem::exists(pid_file); ++i) ::usleep(20000);
  pid_t pid = 0;
  std::ifstream(pid_file) >> pid;
  return pid;
}

// True once `pid` no longer runs (within 2 s): gone, or a zombie (state Z in /proc/PID/stat).
inline bool process_gone(pid_t pid) {
  for (int i = 0; i < 100; ++i) {
    if (::kill(pid, 0) != 0 && errno == ESRCH) return true;
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string pid_text, name, state;
    if (stat >> pid_text >> name >> state && state == "Z") return true;
    ::usleep(20000);
  }
  return false;
}

}  // namespace lrchain::test
