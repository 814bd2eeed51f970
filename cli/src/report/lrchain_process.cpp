// Subcommand execution for `lrchain reproduce` (see lrchain_process.hpp).
#include "lrchain_process.hpp"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "lrchain/output_target.hpp"
#include "lrchain/process.hpp"
#include "lrchain/jobs/figure_format.hpp"
#include "lrchain/jobs/output_files.hpp"

namespace lrchain::report {

namespace fs = std::filesystem;

fs::path current_executable() { return fs::read_symlink("/proc/self/exe"); }

nlohmann::json read_json(const fs::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error("cannot read " + file.string());
  try {
    return nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw std::runtime_error("invalid JSON in " + file.string() + ": " + e.what());
  }
}

namespace {

std::string tail_lines(const fs::path& file, int lines) {
  std::ifstream in(file);
  std::vector<std::string> all;
  for (std::string l; std::getline(in, l);) {
    // progress bars rewrite one line with '\r': keep the last state
    const auto cr = l.find_last_of('\r');
    all.push_back(cr == std::string::npos ? l : l.substr(cr + 1));
  }
  std::string out;
  for (std::size_t i = all.size() > static_cast<std::size_t>(lines) ? all.size() - lines : 0;
       i < all.size(); ++i)
    out += (out.empty() ? "" : " | ") + all[i];
  return out;
}

std::string display(const StepContext& ctx, const std::string& arg) {
  const auto rel = fs::path(arg).lexically_relative(ctx.out);
  if (!arg.empty() && arg[0] == '/' && !rel.empty() && rel.native().rfind("..", 0) != 0)
    return rel.string();
  return arg.find(' ') == std::string::npos ? arg : "'" + arg + "'";
}

}  // namespace

namespace {

// Child runs that are running (pids), read by the signal handler: a fixed array of atomics, as a
// handler may only touch lock-free data.
constexpr int max_children = 128;
std::atomic<pid_t> running_children[max_children];
volatile std::sig_atomic_t received_signal = 0;

extern "C" void pass_signal_on(int signal_number) {
  received_signal = signal_number;
  for (auto& child : running_children) {
    const pid_t pid = child.load();
    if (pid > 0) ::kill(-pid, signal_number);  // the child's own process group: it and its gnuplot
  }
}

// Holds a slot of running_children while the child runs; a signal that came before the slot was
// taken is passed on here.
class RunningChild {
 public:
  explicit RunningChild(const ChildProcess& child) {
    for (int i = 0; i < max_children && slot_ < 0; ++i) {
      pid_t free = 0;
      if (running_children[i].compare_exchange_strong(free, child.pid())) slot_ = i;
    }
    if (received_signal != 0) child.send_signal(received_signal);
  }
  ~RunningChild() {
    if (slot_ >= 0) running_children[slot_].store(0);
  }
  RunningChild(const RunningChild&) = delete;
  RunningChild& operator=(const RunningChild&) = delete;

 private:
  int slot_ = -1;
};

}  // namespace

void forward_interrupts_to_children() {
  struct sigaction action {};
  action.sa_handler = pass_signal_on;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

int interrupt_signal() { return received_signal; }

nlohmann::json run_lrchain(const StepContext& ctx, const std::vector<std::string>& args,
                           const fs::path& dir, const std::string& log_stem,
                           std::vector<std::string>& commands) {
  if (interrupt_signal() != 0) throw std::runtime_error("interrupted before it started");
  jobs::ensure_directory(dir);
  std::vector<std::string> format_args;  // the report's --figure-format, passed to every child
  if (jobs::figure_format() != jobs::FigureFormat::png) format_args = {"--figure-format", jobs::figure_format_name()};
  std::string shown = "lrchain";
  for (const auto& a : args) {
    shown += ' ';
    shown += display(ctx, a);
  }
  for (const auto& a : format_args) {
    shown += ' ';
    shown += display(ctx, a);
  }
  commands.push_back(shown);

  const fs::path out_file = dir / (log_stem + ".json"), err_file = dir / (log_stem + ".log");
  const std::string tmp_suffix = ".tmp." + std::to_string(::getpid());
  const fs::path out_tmp = dir / ("." + log_stem + ".json" + tmp_suffix);
  const fs::path err_tmp = dir / ("." + log_stem + ".log" + tmp_suffix);
  std::vector<std::string> argv{ctx.exe.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  argv.insert(argv.end(), format_args.begin(), format_args.end());
  ProcessOptions options;
  options.stdout_file = out_tmp;
  options.stderr_file = err_tmp;
  options.environment = {"OMP_NUM_THREADS=" + std::to_string(ctx.child_threads)};
  options.own_process_group = true;  // a signal passed on reaches everything the child started
  ProcessResult result;
  {
    ChildProcess child(argv, options);
    const RunningChild running(child);
    result = child.wait();
  }
  std::error_code ec;
  check_output_target(err_file);
  check_output_target(out_file);
  fs::rename(err_tmp, err_file, ec);
  if (!result.ok()) {
    fs::remove(out_tmp, ec);
    const std::string why = result.exited ? "exit code " + std::to_string(result.exit_code)
                                          : "killed by signal " + std::to_string(result.signal_number);
    throw std::runtime_error("`" + shown + "` failed (" + why + "): " + tail_lines(err_file, 4));
  }
  fs::rename(out_tmp, out_file, ec);
  if (ec) throw std::runtime_error("cannot write " + out_file.string() + ": " + ec.message());
  return read_json(out_file);
}

}  // namespace lrchain::report
