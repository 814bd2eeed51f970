#pragma once
// Running another program (gnuplot, the C++ compiler, lrchain itself in the report and tests) with
// an argument vector (fork + execve, PATH searched as execvp does): never a shell, so a path is
// passed as data, not code. Every child dies with its parent: it is started with
// PR_SET_PDEATHSIG = SIGKILL (Linux), so when the lrchain process that started it ends in any way,
// SIGKILL included, the child is killed at once, and so, link by link, is everything it started
// (a `reproduce` killed with SIGKILL leaves no run writing into DIR.partial). The signal follows the
// *thread* that started the child: wait() for a child in the thread that constructed it (every
// caller does). posix_spawn cannot set the parent-death signal, hence the fork.
#include <atomic>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace lrchain {

struct ProcessOptions {
  std::filesystem::path working_directory;        // empty: the caller's
  std::optional<std::filesystem::path> stdout_file; // redirect stdout to this file (truncated)
  std::optional<std::filesystem::path> stderr_file; // redirect stderr to this file (truncated)
  bool capture_stdout = false;                    // collect stdout into ProcessResult::output
  bool capture_stderr = false;                    // collect stderr into ProcessResult::error_output
  bool stdin_null = true;                         // child's stdin from /dev/null
  // The child leads a process group of its own: send_signal() then reaches it and everything it
  // started (e.g. a child lrchain run and its gnuplot), and the terminal's Ctrl-C reaches only the
  // caller, which decides what to pass on.
  bool own_process_group = false;
  // While the child runs, wait() polls this flag (every 50 ms); once it is set, the child (its whole
  // group with own_process_group, e.g. a compiler driver and its cc1plus) gets SIGKILL and
  // ProcessResult::stopped is set. nullptr: wait until the child ends.
  const std::atomic<bool>* stop = nullptr;
  // Extra environment entries "NAME=value" (replace the caller's of the same name); variables
  // named in unset_environment are removed from the child's environment.
  std::vector<std::string> environment;
  std::vector<std::string> unset_environment;
};

struct ProcessResult {
  int exit_code = -1;           // valid when exited
  int signal_number = 0;        // non-zero when killed by a signal
  bool exited = false;
  bool stopped = false;         // killed because ProcessOptions::stop was set
  std::string output;           // stdout, when captured
  std::string error_output;     // stderr, when captured
  bool ok() const { return exited && exit_code == 0; }
};

// A started child process; wait() reaps it. Lets a caller forward signals (kill) while waiting.
class ChildProcess {
 public:
  ChildProcess(const std::vector<std::string>& argv, const ProcessOptions& options = {});
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;
  int pid() const { return pid_; }
  // Sends the signal to the child, or to its whole process group when it has one of its own.
  void send_signal(int signal_number) const;
  ProcessResult wait();  // reads the captured pipes to the end, then waits for the child

 private:
  int pid_ = -1;
  int out_fd_ = -1, err_fd_ = -1;
  bool waited_ = false;
  bool own_group_ = false;
  const std::atomic<bool>* stop_ = nullptr;
};

// Runs argv[0] (looked up in PATH when it has no '/') with argv, waits for it.
// Throws std::runtime_error if the program cannot be started (e.g. not found).
ProcessResult run_program(const std::vector<std::string>& argv, const ProcessOptions& options = {});

// True when `program` is an executable file in PATH (or, with a '/', at that path).
bool program_in_path(const std::string& program);

}  // namespace lrchain
