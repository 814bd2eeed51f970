#pragma once
// TOML experiment configs (examples/*.toml): which experiment, its parameters, the integrator
// and the output directory. Numbers may be TOML numbers or strings in the shared number syntax
// ("1/3", "pi/2", "3*pi/5"). Every file is checked against the schema of its kind
// (lrchain/config/strict_toml.hpp; docs/configs.md lists every key) before anything runs.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"

namespace lrchain::jobs {

struct ExperimentConfig {
  std::string experiment;  // "bright" (drive and modulated: more_experiment_config.hpp)
  std::string name;        // free label, e.g. "exp1-optical-pi-2"
  sim::BrightRunConfig bright;
  std::string out_dir;     // [output] dir, may be empty
};

// The kinds of simulate config: "bright", "drive", "modulated".
std::vector<std::string> experiment_kinds();
// The schema of a simulate config's top level for one kind (its tables are its keys' schemas);
// InvalidParameter("experiment") for another kind.
const lrchain::config::TableSchema& experiment_schema(std::string_view kind);
// The reference of every key of every kind as Markdown (the generated part of docs/configs.md).
std::string experiment_configs_markdown();

// Reads a "bright" config. A file that is not one (missing, empty, malformed, another kind,
// unknown keys, wrong types, values out of range) is a config::ConfigError (an InputError: exit 2)
// naming the file, line and key; cross-key checks of validate(BrightRunConfig) give InvalidParameter.
ExperimentConfig load_experiment_config(const std::filesystem::path& file);
ExperimentConfig load_experiment_config(const lrchain::config::Document& doc);

}  // namespace lrchain::jobs
