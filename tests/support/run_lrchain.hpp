#pragma once
// Running lrchain (and other programs) from the tests with an argument vector through
// lrchain::run_program: no shell, so a path with quotes, spaces or `$(...)` is passed as data.
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "lrchain/process.hpp"

namespace lrchain::test {

struct CommandResult {
  int exit_code = -1;     // -1 when killed by a signal
  int signal_number = 0;  // the signal that killed it, else 0
  std::string out, err;   // stdout, stderr
};

// Runs argv in `cwd` (empty: the test's) with extra environment entries "NAME=value".
inline CommandResult run_command(const std::vector<std::string>& argv, const std::filesystem::path& cwd = {},
                                 const std::vector<std::string>& environment = {}) {
  ProcessOptions options;
  options.working_directory = cwd;
  options.capture_stdout = true;
  options.capture_stderr = true;
  options.environment = environment;
  const ProcessResult r = run_program(argv, options);
  return {r.exited ? r.exit_code : -1, r.signal_number, r.output, r.error_output};
}

#ifdef LRCHAIN_CLI
// `lrchain args...` (the executable under test).
inline CommandResult run_lrchain(const std::vector<std::string>& args, const std::filesystem::path& cwd = {},
                                 const std::vector<std::string>& environment = {}) {
  std::vector<std::string> argv{LRCHAIN_CLI};
  argv.insert(argv.end(), args.begin(), args.end());
  return run_command(argv, cwd, environment);
}
#endif

// "a b  c" -> {"a", "b", "c"}: a command line of plain words (no quoting), as an argv.
inline std::vector<std::string> words(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

}  // namespace lrchain::test
