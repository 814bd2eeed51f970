// lrchain-derive with an unusable --out: exit 2 and one line on stderr before any derivation work,
// nothing created (it used to end in std::terminate from an uncaught filesystem_error).
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "lrchain/process.hpp"

namespace fs = std::filesystem;

TEST_CASE("lrchain-derive --out through a file or into a file is exit 2, one line, nothing written") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-derive-out-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "user data";
  for (const std::string out : {"file", "file/sub"}) {
    INFO("--out " << out);
    lrchain::ProcessOptions o;
    o.working_directory = dir;
    o.capture_stdout = o.capture_stderr = true;
    const auto r = lrchain::run_program({LRCHAIN_DERIVE, "--out", out, "--quiet"}, o);
    CHECK(r.exited);
    CHECK(r.exit_code == 2);
    CHECK(r.error_output.find("--out 'file") != std::string::npos);
    CHECK(std::count(r.error_output.begin(), r.error_output.end(), '\n') == 1);
    CHECK(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}) == 1);
  }
  std::ifstream in(dir / "file");
  std::string text;
  std::getline(in, text);
  CHECK(text == "user data");
  fs::remove_all(dir);
}
