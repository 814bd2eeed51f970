#pragma once
// What the sweep tests share: a fresh scratch directory per test, writing a file, and the short
// bright base config their sweeps run.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace lrchain::test {

// A fresh, empty scratch directory <tmp>/lrchain-<prefix>-<name>-<pid>.
inline std::filesystem::path sweep_scratch(const std::string& prefix, const std::string& name) {
  const auto d = std::filesystem::temp_directory_path() / ("lrchain-" + prefix + "-" + name + "-" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// Writes `text` (bytes as they are) to `file`.
inline void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

// A short optical bright run of the paper's chain (exp1's stepper settings, 121 sites, 10 T_b).
inline constexpr const char* short_bright_base = R"(experiment = "bright"
[model]
rho = "1/3"
[bright]
branch = "optical"
theta = "pi/2"
sites = 121
periods = 10
sample_every = 0.25
spacetime_every = 1.0
snapshot_periods = [0.0]
[integrator]
stepper = "srkn11b"
dt = 0.37
)";

}  // namespace lrchain::test
