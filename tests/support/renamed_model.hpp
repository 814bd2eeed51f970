#pragma once
// A shipped model file under another model name, written outside models/: the same equations, but
// a user's file (its bytes are no shipped file's), so lrchain compiles its code at run time.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

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

}  // namespace lrchain::test
