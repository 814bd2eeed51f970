#pragma once
// TOML configs of experiments 6 ("drive", Sec. 4.3) and 7 ("modulated", Sec. 5.1). The bright
// experiments, and the schemas of all three kinds, are in experiment_config.hpp. Numbers may be
// TOML numbers or strings in the shared syntax ("1/3", "pi/2", "252*pi/401").
#include <filesystem>
#include <string>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/sim/drive_run.hpp"
#include "lrchain/sim/modulated_run.hpp"

namespace lrchain::jobs {

// The top-level `experiment` key of a config: "bright", "drive" or "modulated". A file that cannot
// be read or parsed, or whose `experiment` is missing or another value, is a config::ConfigError.
std::string experiment_kind(const std::filesystem::path& file);
std::string experiment_kind(const lrchain::config::Document& doc);

struct DriveExperiment {
  std::string name, out_dir;
  sim::DriveRunConfig run;
};
struct ModulatedExperiment {
  std::string out_dir;
  sim::ModulatedRunConfig run;  // run.name = config name
};

// Read and check a config of that kind (config::ConfigError naming file, line and key; the
// cross-key checks of validate() give InvalidParameter).
DriveExperiment load_drive_config(const std::filesystem::path& file);
DriveExperiment load_drive_config(const lrchain::config::Document& doc);
ModulatedExperiment load_modulated_config(const std::filesystem::path& file);
ModulatedExperiment load_modulated_config(const lrchain::config::Document& doc);

}  // namespace lrchain::jobs
