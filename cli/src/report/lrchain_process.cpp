// Subcommand execution for `lrchain reproduce` (see lrchain_process.hpp).
#include "lrchain_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "lrchain/sim/output_files.hpp"

extern char** environ;

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

nlohmann::json run_lrchain(const StepContext& ctx, const std::vector<std::string>& args,
                           const fs::path& dir, const std::string& log_stem,
                           std::vector<std::string>& commands) {
  sim::ensure_directory(dir);
  std::string shown = "lrchain";
  for (const auto& a : args) {
    shown += ' ';
    shown += display(ctx, a);
  }
  commands.push_back(shown);

  const fs::path out_file = dir / (log_stem + ".json"), err_file = dir / (log_stem + ".log");
  std::vector<std::string> argv_storage{ctx.exe.string()};
  argv_storage.insert(argv_storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_storage) argv.push_back(a.data());
  argv.push_back(nullptr);

  std::vector<std::string> env_storage;
  for (char** e = environ; *e; ++e)
    if (std::string(*e).rfind("OMP_NUM_THREADS=", 0) != 0) env_storage.emplace_back(*e);
  env_storage.push_back("OMP_NUM_THREADS=" + std::to_string(ctx.child_threads));
  std::vector<char*> envp;
  for (auto& e : env_storage) envp.push_back(e.data());
  envp.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, out_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 2, err_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) throw std::runtime_error("cannot start " + ctx.exe.string());
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) throw std::runtime_error("waitpid failed");
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string why = WIFEXITED(status) ? "exit code " + std::to_string(WEXITSTATUS(status))
                                              : "killed by signal " + std::to_string(WTERMSIG(status));
    throw std::runtime_error("`" + shown + "` failed (" + why + "): " + tail_lines(err_file, 4));
  }
  return read_json(out_file);
}

}  // namespace lrchain::report
