// Spawning programs with an argv (process.hpp): posix_spawnp, optional pipes, no shell.
#include "lrchain/process.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
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

// Collects both captured pipes until they close (poll, so neither pipe can fill and block).
void drain(int out_fd, int err_fd, std::string& out, std::string& err) {
  char buf[65536];
  while (out_fd >= 0 || err_fd >= 0) {
    pollfd fds[2];
    int n = 0;
    if (out_fd >= 0) fds[n++] = {out_fd, POLLIN, 0};
    if (err_fd >= 0) fds[n++] = {err_fd, POLLIN, 0};
    if (::poll(fds, n, -1) < 0) {
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
}

}  // namespace

ChildProcess::ChildProcess(const std::vector<std::string>& argv_in, const ProcessOptions& o) {
  if (argv_in.empty()) throw std::invalid_argument("run_program: empty argv");
  std::vector<std::string> args = argv_in, env = child_environment(o);
  auto argv = c_strings(args), envp = c_strings(env);

  int out_pipe[2] = {-1, -1}, err_pipe[2] = {-1, -1};
  if (o.capture_stdout && ::pipe2(out_pipe, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");
  if (o.capture_stderr && ::pipe2(err_pipe, O_CLOEXEC) != 0) throw std::runtime_error("pipe failed");

  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  if (!o.working_directory.empty())
    posix_spawn_file_actions_addchdir_np(&fa, o.working_directory.c_str());
  if (o.stdin_null) posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  if (o.capture_stdout) posix_spawn_file_actions_adddup2(&fa, out_pipe[1], 1);
  else if (o.stdout_file)
    posix_spawn_file_actions_addopen(&fa, 1, o.stdout_file->c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (o.capture_stderr) posix_spawn_file_actions_adddup2(&fa, err_pipe[1], 2);
  else if (o.stderr_file)
    posix_spawn_file_actions_addopen(&fa, 2, o.stderr_file->c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);

  // The child starts with default signal dispositions and an empty mask, whatever the caller set.
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  sigset_t all, none;
  sigfillset(&all);
  sigemptyset(&none);
  posix_spawnattr_setsigdefault(&attr, &all);
  posix_spawnattr_setsigmask(&attr, &none);
  short flags = POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK;
  if (o.own_process_group) {
    posix_spawnattr_setpgroup(&attr, 0);  // a new group whose id is the child's pid
    flags |= POSIX_SPAWN_SETPGROUP;
  }
  posix_spawnattr_setflags(&attr, flags);

  pid_t pid = -1;
  const int rc = ::posix_spawnp(&pid, argv[0], &fa, &attr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&fa);
  posix_spawnattr_destroy(&attr);
  for (int fd : {out_pipe[1], err_pipe[1]})
    if (fd >= 0) ::close(fd);
  if (rc != 0) {
    for (int fd : {out_pipe[0], err_pipe[0]})
      if (fd >= 0) ::close(fd);
    throw std::runtime_error("cannot start '" + argv_in[0] + "': " + std::strerror(rc));
  }
  pid_ = pid;
  own_group_ = o.own_process_group;
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
  drain(out_fd_, err_fd_, r.output, r.error_output);
  out_fd_ = err_fd_ = -1;
  int status = 0;
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
