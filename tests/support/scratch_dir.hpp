#pragma once
// A fresh, empty scratch directory for one test case under the system's temporary directory,
// named by the test and this process, so that parallel test processes never share one.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace lrchain::test {

inline std::filesystem::path scratch_directory(const std::string& name) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("lrchain-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace lrchain::test
