#pragma once
// The model file of a sweep whose base is a model-file simulate config (`model = "models/x.toml"`,
// experiment "bright" or "ring"; model_experiment_config.hpp): loaded once per sweep, its
// definition (evaluators) and lattice kernels together, then shared by every point and thread;
// each point builds its Model from the definition and the point's [parameters] values.
#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_abi.h"

namespace lrchain::jobs::sweep {

struct ModelFile {
  std::string path;                                        // as the base config names it
  std::shared_ptr<const ModelDefinition> definition;       // evaluators, parameters, branches
  std::shared_ptr<const lrchain_lattice_kernels> kernels;  // keeps a run-time compiled library loaded
};

// Loads a model file's definition and lattice kernels (InputError for a missing or bad file). The
// front end injects its loader, which may compile a user's file; without one, load_shipped_model_file.
using ModelFileLoader = std::function<ModelFile(const std::string& path)>;

// A model file whose bytes are a shipped model's (models/*.toml), with its compiled-in evaluators
// and lattice kernels; InputError naming the file otherwise (missing, or not a shipped model: a
// front end that compiles model files passes its own loader).
ModelFile load_shipped_model_file(const std::string& path);

}  // namespace lrchain::jobs::sweep
