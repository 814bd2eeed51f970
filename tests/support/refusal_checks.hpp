#pragma once
// The bad-input contract checked from the tests: exit 2, one line on stderr naming the problem,
// nothing on stdout and nothing written to --out.
#include <doctest/doctest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "run_lrchain.hpp"

namespace lrchain::test {

#ifdef LRCHAIN_CLI
// Runs `lrchain args... --out DIR` in `cwd` (DIR a scratch path that must not appear) and checks
// the refusal: exit 2, one stderr line containing `needle`, empty stdout.
inline void check_refused_run(std::vector<std::string> args, const std::string& needle,
                              const std::filesystem::path& cwd = {}) {
  namespace fs = std::filesystem;
  const fs::path out = fs::temp_directory_path() / ("lrchain-refused-" + std::to_string(::getpid()));
  fs::remove_all(out);
  args.insert(args.end(), {"--out", out.string()});
  const auto r = run_lrchain(args, cwd);
  INFO(r.err);
  CHECK(r.exit_code == 2);
  CHECK(r.err.find(needle) != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(r.out.empty());
  CHECK(!fs::exists(out));
}
#endif

}  // namespace lrchain::test
