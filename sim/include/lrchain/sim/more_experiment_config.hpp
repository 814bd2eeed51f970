#pragma once
// TOML configs of experiments 6 ("drive", Sec. 4.3) and 7 ("modulated", Sec. 5.1). The bright
// experiments stay in experiment_config.hpp. Numbers may be TOML numbers or strings in the shared
// syntax ("1/3", "pi/2", "252*pi/401").
#include <filesystem>
#include <string>

#include "lrchain/sim/drive_run.hpp"
#include "lrchain/sim/modulated_run.hpp"

namespace lrchain::sim {

// The top-level `experiment` key of a config file ("" if absent); throws std::runtime_error if
// the file cannot be read or parsed.
std::string experiment_kind(const std::filesystem::path& file);

struct DriveExperiment {
  std::string name, out_dir;
  DriveRunConfig run;
};
struct ModulatedExperiment {
  std::string out_dir;
  ModulatedRunConfig run;  // run.name = config name
};

// Throw InvalidParameter naming the key for wrong types or values.
DriveExperiment load_drive_config(const std::filesystem::path& file);
ModulatedExperiment load_modulated_config(const std::filesystem::path& file);

}  // namespace lrchain::sim
