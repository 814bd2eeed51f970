// Spawning programs with an argv (process.hpp): fork + execve, optional pipes, no shell; the child
// dies with its parent (PR_SET_PDEATHSIG).
#include "lrchain/process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <pthread.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace lrchain {

namespace {

std::string env_name(const std::string& entry) { return entry.substr(0, entry.find('=')); }

// The child's environment: the caller's, minus unset and overridden names, plus the extras.
std::vector<std::string> child_environment(const ProcessOptions& o) {
  std::vector<std::string> env;
  for (char** e = environ; e && *e; ++e) {
    const std::string entry(*e), name = env_name(entry);
    bool drop = false;
    for (const auto& u : o.unset_environment) drop = drop || u == name;
    for (const auto& x : o.environment) drop = drop || env_name(x) == name;
    if (!drop) env.push_back(entry);
  }
  env.insert(env.end(), o.environment.begin(), o.environment.end());
  return env;
}

std::vector<char*> c_strings(std::vector<std::string>& v) {
  std::vector<char*> out;
  for (auto& s : v) out.push_back(s.data());
  out.push_back(nullptr);
  return out;
}

bool stop_set(const std::atomic<bool>* stop) { return stop && stop->load(std::memory_order_relaxed); }

// Collects both captured pipes until they close (poll, so neither pipe can fill and block); returns
// early (false) once `stop` is set, polling it every 50 ms.
bool drain(int& out_fd, int& err_fd, std::string& out, std::string& err, const std::atomic<bool>* stop) {
  char buf[65536];
  while (out_fd >= 0 || err_fd >= 0) {
    if (stop_set(stop)) return false;
    pollfd fds[2];
    int n = 0;
    if (out_fd >= 0) fds[n++] = {out_fd, POLLIN, 0};
    if (err_fd >= 0) fds[n++] = {err_fd, POLLIN, 0};
    const int ready = ::poll(fds, n, stop ? 50 : -1);
    if (ready == 0) continue;
    if (ready < 0) {
      if (errno == EINTR) continue;
      break;
    }
    for (int i = 0; i < n; ++i) {
      if (!(fds[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const ssize_t r = ::read(fds[i].fd, buf, sizeof buf);
      if (r < 0 && errno == EINTR) continue;
      std::string& dst = fds[i].fd == out_fd ? out : err;
      if (r > 0) {
        dst.append(buf, std::size_t(r));
      } else {
        ::close(fds[i].fd);
        (fds[i].fd == out_fd ? out_fd : err_fd) = -1;
      }
    }
  }
  return true;
}

}  // namespace

namespace {

// Where execvp would look for `program`: itself when it has a '/', else each PATH directory
// (the caller's PATH; "." for an empty entry), in order.
std::vector<std::string> program_candidates(const std::string& program) {
  if (program.find('/') != std::string::npos) return {program};
  const char* path = std::getenv("PATH");
  const std::string dirs = path ? path : "/usr/bin:/bin";
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    out.push_back((end > start ? dirs.substr(start, end - start) : std::string(".")) + "/" + program);
    start = end + 1;
  }
  return out;
}

// In the forked child (async-signal-safe calls only): reports errno on `error_fd` and exits 127.
[[noreturn]] void child_fails(int error_fd) {
  const int e = errno;
  [[maybe_unused]] const ssize_t w = ::write(error_fd, &e, sizeof e);
  ::_exit(127);
}

// In the forked child: puts `path` opened with `flags` at descriptor `fd`.
void open_at(const char* path, int flags, int fd, int error_fd) {
  const int opened = ::open(path, flags | O_CLOEXEC, 0644);
  if (opened < 0 || ::dup2(opened, fd) < 0) child_fails(error_fd);
  ::close(opened);
}

}  // namespace

// fork, then in the child (async-signal-safe calls only, everything allocated before the fork):
// default signal dispositions, the process group, PR_SET_PDEATHSIG, directory, descriptors, the
// caller's signal mask emptied, execve over the PATH candidates. An exec failure's errno comes
// back through a close-on-exec pipe, so a program that cannot start is an exception here.
ChildProcess::ChildProcess(const std::vector<std::string>& argv_in, const ProcessOptions& o) {
  if (argv_in.empty()) throw std::invalid_argument("run_program: empty argv");
  std::vector<std::string> args = argv_in, env = child_environment(o), programs = program_candidates(argv_in[0]);
  auto argv = c_strings(args), envp = c_strings(env);
  const std::string directory = o.working_directory.string();
  const std::string out_file = o.stdout_file ? o.stdout_file->string() : std::string();
  const std::string err_file = o.stderr_file ? o.stderr_file->string() : std::string();

  int out_pipe[2] = {-1, -1}, err_pipe[2] = {-1, -1}, error_pipe[2] = {-1, -1};
  const auto close_all = [&] {
    for (int fd : {out_pipe[0], out_pipe[1], err_pipe[0], err_pipe[1], error_pipe[0], error_pipe[1]})
      if (fd >= 0) ::close(fd);
  };
  if ((o.capture_stdout && ::pipe2(out_pipe, O_CLOEXEC) != 0) ||
      (o.capture_stderr && ::pipe2(err_pipe, O_CLOEXEC) != 0) || ::pipe2(error_pipe, O_CLOEXEC) != 0) {
    close_all();
    throw std::runtime_error("pipe failed");
  }

  // No signal handler of the caller may run in the child before it resets them.
  sigset_t all, caller_mask;
  sigfillset(&all);
  ::pthread_sigmask(SIG_SETMASK, &all, &caller_mask);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int error_fd = error_pipe[1];
    struct sigaction default_action {};
    default_action.sa_handler = SIG_DFL;
    for (int signal_number = 1; signal_number < NSIG; ++signal_number)
      ::sigaction(signal_number, &default_action, nullptr);  // (fails harmlessly for KILL, STOP)
    if (o.own_process_group && ::setpgid(0, 0) != 0) child_fails(error_fd);
    // Dies with the thread that started it (the caller waits for it there): a SIGKILLed lrchain
    // leaves no child writing into its outputs. If the parent is already gone, stop here.
    if (::prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) child_fails(error_fd);
    if (::getppid() != parent) ::_exit(127);
    if (!directory.empty() && ::chdir(directory.c_str()) != 0) child_fails(error_fd);
    if (o.stdin_null) open_at("/dev/null", O_RDONLY, 0, error_fd);
    if (o.capture_stdout) {
      if (::dup2(out_pipe[1], 1) < 0) child_fails(error_fd);
    } else if (o.stdout_file) {
      open_at(out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 1, error_fd);
    }
    if (o.capture_stderr) {
      if (::dup2(err_pipe[1], 2) < 0) child_fails(error_fd);
    } else if (o.stderr_file) {
      open_at(err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 2, error_fd);
    }
    sigset_t none;
    sigemptyset(&none);
    ::sigprocmask(SIG_SETMASK, &none, nullptr);
    // execvp's search: go on past a candidate that is missing or not executable.
    int failure = ENOENT;
    for (const auto& program : programs) {
      ::execve(program.c_str(), argv.data(), envp.data());
      if (errno != ENOENT && errno != ENOTDIR) failure = errno;
      if (errno != ENOENT && errno != ENOTDIR && errno != EACCES) break;
    }
    errno = failure;
    child_fails(error_fd);
  }
  const int fork_errno = errno;
  ::pthread_sigmask(SIG_SETMASK, &caller_mask, nullptr);
  for (int* fd : {&out_pipe[1], &err_pipe[1], &error_pipe[1]})
    if (*fd >= 0) {
      ::close(*fd);
      *fd = -1;
    }
  int child_errno = 0;
  if (pid > 0) {
    ssize_t n;
    while ((n = ::read(error_pipe[0], &child_errno, sizeof child_errno)) < 0 && errno == EINTR) {
    }
    if (n != ssize_t(sizeof child_errno)) child_errno = 0;  // closed by the exec: started
  }
  ::close(error_pipe[0]);
  error_pipe[0] = -1;
  if (pid < 0 || child_errno != 0) {
    if (pid > 0)
      while (::waitpid(pid, nullptr, 0) < 0 && errno == EINTR) {
      }
    close_all();
    throw std::runtime_error("cannot start '" + argv_in[0] + "': " + std::strerror(pid < 0 ? fork_errno : child_errno));
  }
  if (o.own_process_group) ::setpgid(pid, pid);  // (also in the child: whichever runs first)
  pid_ = pid;
  own_group_ = o.own_process_group;
  stop_ = o.stop;
  out_fd_ = out_pipe[0];
  err_fd_ = err_pipe[0];
}

ChildProcess::~ChildProcess() {
  if (!waited_ && pid_ > 0) {
    send_signal(SIGTERM);
    wait();
  }
}

void ChildProcess::send_signal(int signal_number) const {
  if (!waited_ && pid_ > 0) ::kill(own_group_ ? -pid_ : pid_, signal_number);
}

ProcessResult ChildProcess::wait() {
  ProcessResult r;
  if (waited_) return r;
  bool stopped = !drain(out_fd_, err_fd_, r.output, r.error_output, stop_);
  int status = 0;
  // With a stop flag, the child is polled (it may have closed its pipes and still run).
  while (stop_ && !stopped) {
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done == pid_ || (done < 0 && errno != EINTR)) break;
    if (stop_set(stop_)) {
      stopped = true;
      break;
    }
    ::usleep(50000);
  }
  if (stopped) {
    send_signal(SIGKILL);  // the group when it has one: the compiler's own children too
    r.stopped = true;
  }
  for (int* fd : {&out_fd_, &err_fd_})
    if (*fd >= 0) {
      ::close(*fd);
      *fd = -1;
    }
  if (stopped || !stop_)
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
  waited_ = true;
  if (WIFEXITED(status)) {
    r.exited = true;
    r.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    r.signal_number = WTERMSIG(status);
  }
  return r;
}

ProcessResult run_program(const std::vector<std::string>& argv, const ProcessOptions& options) {
  ChildProcess child(argv, options);
  return child.wait();
}

bool program_in_path(const std::string& program) {
  if (program.empty()) return false;
  if (program.find('/') != std::string::npos) return ::access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = std::min(dirs.find(':', start), dirs.size());
    const std::string dir = end > start ? dirs.substr(start, end - start) : ".";
    if (::access((dir + "/" + program).c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

}  // namespace lrchain
