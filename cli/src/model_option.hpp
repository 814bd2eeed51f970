#pragma once
// --model FILE and --set NAME=VALUE for the commands that evaluate a lattice model (docs/models.md).
// Without --model the command uses the resonant chain and its --alpha/--delta0/--kappa/--rho.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <memory>
#include <string>
#include <vector>

#include "lrchain/jobs/model_source.hpp"
#include "lrchain/model.hpp"
#include "lrchain/model_json.hpp"
#include "lrchain/params.hpp"

namespace lrchain::cli {

struct ModelSelection {
  std::string file;              // empty: the resonant chain through Params
  std::vector<std::string> set;  // NAME=VALUE
  // The loaded model (load_selected_model), whose lattice kernels lattice_kernels_for hands out.
  mutable std::shared_ptr<const jobs::ModelSource> source{};
};

// The run-time model compiler the CLI injects into the model loader (jobs::ModelSource): SIGINT/SIGTERM
// stop a compile (exit 130/143), the GiNaC fallback is a warning on stderr; null in a build without it.
std::shared_ptr<const jobs::ModelCompiler> model_compiler();

// Adds --model and --set to `cmd`.
void add_model_file_options(CLI::App& cmd, ModelSelection& selection);

// The model of `selection` through the model loader (jobs::ModelSource, with the model compiler
// injected and SIGINT/SIGTERM stopping a compile: exit 130/143). The resonant chain's
// --alpha/--delta0/--kappa/--rho (given on `cmd`) are aliases for --set; for other models they are
// an error. With `lattice_run`, a user's file is refused (InputError) before anything else when its
// lattice code can be neither found in the cache nor compiled (no compiler).
Model load_selected_model(const ModelSelection& selection, const CLI::App& cmd, const Params& resonant_aliases,
                          bool lattice_run = false);

// Where a model's lattice kernels came from, for the JSON output.
using LatticeCode = jobs::LatticeCode;

// The lattice kernels of `model` (loaded from `selection` by load_selected_model): the compiled-in
// kernels of a shipped model file, else the same file's lattice code compiled at run time into the
// model cache (InputError, exit 2, when the compiler is not installed).
LatticeCode lattice_kernels_for(const ModelSelection& selection, const Model& model);

// {"compiled_in", "seconds", "from_cache", "library"} of `code`.
using jobs::lattice_code_json;

}  // namespace lrchain::cli
