#pragma once
// --model FILE and --set NAME=VALUE for the commands that evaluate a lattice model (docs/models.md).
// Without --model the command uses the resonant chain and its --alpha/--delta0/--kappa/--rho.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <memory>
#include <string>
#include <vector>

#include "lrchain/model.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/params.hpp"
#include "lrchain/sim/model_lattice_abi.h"

namespace lrchain::cli {

struct ModelSelection {
  std::string file;              // empty: the resonant chain through Params
  std::vector<std::string> set;  // NAME=VALUE
};

// Adds --model and --set to `cmd`.
void add_model_file_options(CLI::App& cmd, ModelSelection& selection);

// The model of `selection`: a shipped model when the file's bytes are a shipped model file's,
// otherwise the file compiled at run time. The resonant chain's --alpha/--delta0/--kappa/--rho
// (given on `cmd`) are aliases for --set; for other models they are an error.
// With `lattice_run`, a user's file is refused (InputError) before anything else when its lattice
// code can be neither found in the cache nor compiled (no compiler).
Model load_selected_model(const ModelSelection& selection, const CLI::App& cmd, const Params& resonant_aliases,
                          bool lattice_run = false);

// Where a model's lattice kernels came from, for the JSON output.
struct LatticeCode {
  std::shared_ptr<const lrchain_lattice_kernels> kernels;  // keeps a run-time compiled library loaded
  bool compiled_in = true;   // shipped model file; else compiled at run time into the model cache
  bool from_cache = false;   // run time: the cached library existed already
  std::string library;       // run time: the cached shared object
  double seconds = 0;        // time to find, compile and load the kernels
};

// The lattice kernels of `model` (loaded from `selection` by load_selected_model): the compiled-in
// kernels of a shipped model file, else the file's lattice code compiled at run time into the
// model cache like its evaluators (InputError, exit 2, when the compiler is not installed).
LatticeCode lattice_kernels_for(const ModelSelection& selection, const Model& model);

// {"compiled_in", "from_cache", "library", "seconds"} of `code`.
nlohmann::json lattice_code_json(const LatticeCode& code);

}  // namespace lrchain::cli
