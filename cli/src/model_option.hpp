#pragma once
// --model FILE and --set NAME=VALUE for the commands that evaluate a lattice model (docs/models.md).
// Without --model the command uses the resonant chain and its --alpha/--delta0/--kappa/--rho.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "lrchain/model.hpp"
#include "lrchain/params.hpp"

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
Model load_selected_model(const ModelSelection& selection, const CLI::App& cmd, const Params& resonant_aliases);

// The resonant chain at `p` as a Model (the shipped definition).
Model resonant_chain_model(const Params& p);

// {"name", "file_hash", "parameters": {name: value, ...}} for JSON output.
nlohmann::json model_json(const Model& model);

}  // namespace lrchain::cli
