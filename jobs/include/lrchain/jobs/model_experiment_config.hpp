#pragma once
// Configs of any model file: `experiment = "bright"` (a bright breather from the NLS ansatz,
// table `[bright]`) or `"ring"` (plane waves and a packet on a periodic ring, table `[ring]`);
// `model = "models/x.toml"` (a path, relative to the directory lrchain runs in), a `[parameters]`
// table (values of the model's parameters; the model's defaults otherwise) and `[output]`. Checked by the strict schema layer
// (lrchain/config/strict_toml.hpp): unknown keys, wrong types and ranges are errors naming the
// file, line and key; parameter names are checked against the model when it is loaded.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/sim/bright_run.hpp"
#include "lrchain/sim/ring_run.hpp"

namespace lrchain::jobs {

struct ModelExperimentConfig {
  std::string experiment;  // "bright" or "ring"
  std::string name;
  std::string model_file;
  std::vector<std::pair<std::string, double>> parameters;  // [parameters], sorted by name
  std::string branch;
  sim::ModelBrightConfig bright;  // experiment "bright"; branch index left at 0: resolved once the model is loaded
  sim::RingRunConfig ring;        // experiment "ring"; branch index likewise
  std::string out_dir;
};

// True when the config's top-level `model` is a string (a model file), not the resonant chain's
// [model] table.
bool is_model_experiment(const lrchain::config::Document& doc);
// The schema of a model config of this experiment ("bright" or "ring"), its tables included.
const lrchain::config::TableSchema& model_experiment_schema(const std::string& experiment);
// Reads a checked model config (ConfigError naming file, line and key otherwise).
ModelExperimentConfig load_model_experiment_config(const lrchain::config::Document& doc);

}  // namespace lrchain::jobs
