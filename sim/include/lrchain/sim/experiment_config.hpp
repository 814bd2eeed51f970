#pragma once
// TOML experiment configs (examples/*.toml): which experiment, its parameters, the integrator
// and the output directory. Numbers may be TOML numbers or strings in the shared number syntax
// ("1/3", "pi/2", "3*pi/5").
#include <filesystem>
#include <string>

#include "lrchain/sim/bright_run.hpp"

namespace lrchain::sim {

struct ExperimentConfig {
  std::string experiment;  // "bright" (more to come: "drive", "modulated")
  std::string name;        // free label, e.g. "exp1-optical-pi-2"
  BrightRunConfig bright;
  std::string out_dir;     // [output] dir, may be empty
};

// Throws InvalidParameter naming the key for unknown experiments, wrong types or bad values,
// std::runtime_error if the file cannot be read or parsed.
ExperimentConfig load_experiment_config(const std::filesystem::path& file);

}  // namespace lrchain::sim
