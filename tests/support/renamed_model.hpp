#pragma once
// A shipped model file under another model name, written outside models/: the same equations, but
// a user's file (its bytes are no shipped file's), so lrchain compiles its code at run time.
#include <doctest/doctest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "run_lrchain.hpp"

namespace lrchain::test {

// models/<shipped>.toml of `source_dir` with `name = "<shipped>"` replaced by `name = "<name>"`, to `path`.
inline void write_renamed_model(const std::filesystem::path& source_dir, const std::string& shipped,
                                const std::string& name, const std::filesystem::path& path) {
  std::ifstream in(source_dir / "models" / (shipped + ".toml"));
  std::stringstream text;
  text << in.rdbuf();
  std::string s = text.str();
  const std::string from = "name = \"" + shipped + "\"";
  const auto at = s.find(from);
  REQUIRE(at != std::string::npos);
  s.replace(at, from.size(), "name = \"" + name + "\"");
  std::ofstream(path) << s;
}

// The JSON of `lrchain dark solve --model models/<shipped>.toml OPTIONS` and of the same run on its
// copy renamed `name` in `dir` (lattice code compiled into dir/cache); both must exit 0.
inline std::pair<nlohmann::json, nlohmann::json> dark_solve_shipped_and_renamed(
    const std::filesystem::path& source_dir, const std::string& shipped, const std::string& name,
    const std::filesystem::path& dir, const std::vector<std::string>& options) {
  const std::filesystem::path copy = dir / (name + ".toml");
  write_renamed_model(source_dir, shipped, name, copy);
  std::vector<std::string> a{"dark", "solve", "--model", "models/" + shipped + ".toml"};
  std::vector<std::string> b{"dark", "solve", "--model", copy.string()};
  a.insert(a.end(), options.begin(), options.end());
  b.insert(b.end(), options.begin(), options.end());
  const auto ra = run_lrchain(a, source_dir);
  const auto rb = run_lrchain(b, source_dir, {"XDG_CACHE_HOME=" + (dir / "cache").string()});
  INFO(ra.err << rb.err);
  REQUIRE(ra.exit_code == 0);
  REQUIRE(rb.exit_code == 0);
  return {nlohmann::json::parse(ra.out), nlohmann::json::parse(rb.out)};
}

}  // namespace lrchain::test
