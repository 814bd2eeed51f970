// run_program (lrchain/process.hpp): argv passed as data, never through a shell.
#include <doctest/doctest.h>
#include <signal.h>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <fstream>

#include "../support/process_checks.hpp"
#include "lrchain/process.hpp"

namespace fs = std::filesystem;

TEST_CASE("run_program passes shell metacharacters as plain arguments") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-process-test-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string evil = "$(touch INJECTED); echo 'x' \"y\" ";
  lrchain::ProcessOptions o;
  o.working_directory = dir;
  o.capture_stdout = true;
  const auto r = lrchain::run_program({"printf", "%s|", evil, "two words"}, o);
  CHECK(r.ok());
  CHECK(r.output == evil + "|two words|");
  CHECK_FALSE(fs::exists(dir / "INJECTED"));
  fs::remove_all(dir);
}

TEST_CASE("run_program reports exit codes, stderr and a missing program") {
  lrchain::ProcessOptions o;
  o.capture_stderr = true;
  const auto r = lrchain::run_program({"ls", "/nonexistent-lrchain-path"}, o);
  CHECK(r.exited);
  CHECK(r.exit_code != 0);
  CHECK_FALSE(r.error_output.empty());
  CHECK_THROWS(lrchain::run_program({"lrchain-no-such-program-xyz"}));
  CHECK_FALSE(lrchain::program_in_path("lrchain-no-such-program-xyz"));
  CHECK(lrchain::program_in_path("ls"));
}

TEST_CASE("run_program sets and removes environment variables") {
  lrchain::ProcessOptions o;
  o.capture_stdout = true;
  o.environment = {"LRCHAIN_PROCESS_TEST=42"};
  o.unset_environment = {"HOME"};
  const auto r = lrchain::run_program({"env"}, o);
  CHECK(r.output.find("LRCHAIN_PROCESS_TEST=42\n") != std::string::npos);
  CHECK(r.output.find("\nHOME=") == std::string::npos);
}

TEST_CASE("process: a child in its own process group leads it, and send_signal reaches the group") {
  // reproduce starts each child run this way, so that SIGINT/SIGTERM passed on reaches the child's
  // own children (gnuplot) too, and the terminal's Ctrl-C reaches reproduce alone.
  lrchain::ProcessOptions o;
  o.own_process_group = true;
  lrchain::ChildProcess child({"sleep", "30"}, o);
  CHECK(::getpgid(child.pid()) == child.pid());
  CHECK(::getpgid(child.pid()) != ::getpgrp());
  child.send_signal(SIGTERM);
  const auto r = child.wait();
  CHECK_FALSE(r.exited);
  CHECK(r.signal_number == SIGTERM);
  // Without the option the child stays in the caller's group.
  lrchain::ChildProcess same({"sleep", "30"});
  CHECK(::getpgid(same.pid()) == ::getpgrp());
  same.send_signal(SIGTERM);
  CHECK(same.wait().signal_number == SIGTERM);
}

TEST_CASE("a child of run_program dies with its parent, also when the parent is killed with SIGKILL") {
  // A stand-in parent (forked here) starts `sleep 60` through ChildProcess, reports its pid and
  // waits; the parent gets SIGKILL. Before (posix_spawn, no parent-death signal) the sleep lived on.
  int pipe_fds[2];
  REQUIRE(::pipe(pipe_fds) == 0);
  const pid_t parent = ::fork();
  REQUIRE(parent >= 0);
  if (parent == 0) {
    ::close(pipe_fds[0]);
    lrchain::ChildProcess child({"sleep", "60"});
    const int pid = child.pid();
    [[maybe_unused]] const auto written = ::write(pipe_fds[1], &pid, sizeof pid);
    child.wait();
    ::_exit(0);
  }
  ::close(pipe_fds[1]);
  int child = 0;
  REQUIRE(::read(pipe_fds[0], &child, sizeof child) == ssize_t(sizeof child));
  ::close(pipe_fds[0]);
  ::kill(parent, SIGKILL);
  ::waitpid(parent, nullptr, 0);
  // Gone (or a zombie waiting for init to reap it) within two seconds.
  const auto alive = [child] {
    std::ifstream stat("/proc/" + std::to_string(child) + "/stat");
    std::string pid, name, state;
    return bool(stat >> pid >> name >> state) && state != "Z";
  };
  for (int i = 0; i < 200 && alive(); ++i) ::usleep(10000);
  CHECK_FALSE(alive());
  if (alive()) ::kill(child, SIGKILL);
}

namespace {

// A fake compiler: a shell script that starts a long-lived grandchild (sleep 300), writes its pid
// to `pid_file`, and waits for it, as g++ waits for cc1plus.
fs::path fake_compiler_with_grandchild(const fs::path& dir, const fs::path& pid_file) {
  const fs::path script = dir / "fake-compiler.sh";
  std::ofstream(script) << "#!/bin/sh\nsleep 300 &\necho $! > " << pid_file.string() << ".tmp\nmv "
                        << pid_file.string() << ".tmp " << pid_file.string() << "\nwait\n";
  fs::permissions(script, fs::perms::owner_all);
  return script;
}

}  // namespace

TEST_CASE("process: a stop flag kills the child's whole process group, grandchildren included") {
  // Before: only the direct child could be reached (PR_SET_PDEATHSIG), so a compiler driver's
  // cc1plus kept running after lrchain stopped; here the sleep plays cc1plus.
  const fs::path dir = fs::temp_directory_path() / ("lrchain-process-group-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const fs::path pid_file = dir / "grandchild.pid";
  const fs::path script = fake_compiler_with_grandchild(dir, pid_file);
  std::atomic<bool> stop{false};
  lrchain::ProcessOptions o;
  o.own_process_group = true;
  o.capture_stderr = true;
  o.stop = &stop;
  lrchain::ChildProcess child({script.string()}, o);
  const pid_t grandchild = lrchain::test::wait_for_pid_file(pid_file, 4);
  REQUIRE(grandchild > 0);
  CHECK(::kill(grandchild, 0) == 0);
  stop = true;
  const auto t0 = std::chrono::steady_clock::now();
  const lrchain::ProcessResult r = child.wait();
  CHECK(r.stopped);
  CHECK(r.signal_number == SIGKILL);
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() < 1.0);
  CHECK(lrchain::test::process_gone(grandchild));
  fs::remove_all(dir);
}
