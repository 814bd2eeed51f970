#pragma once
// lrchain.Model as C++: a model definition with parameter values, the file it was loaded from, and
// (once a lattice run asks for it) its lattice kernels: compiled into lrchain for a shipped model,
// compiled at run time into the per-user cache for a user's file (through lrchain._model_compiler).
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_abi.h"

namespace lrchain::python {

struct LoadedModel {
  std::shared_ptr<const ModelDefinition> definition;
  Model model;
  std::string source;  // the model file's path as given (a shipped model's name: empty)
  // Lattice kernels, loaded on first use (with the GIL held); keeps a run-time library loaded.
  mutable std::shared_ptr<const lrchain_lattice_kernels> lattice{};
  mutable bool lattice_compiled_in = true, lattice_from_cache = false;
  mutable std::string lattice_library{};
};

// The lattice kernels of `m` (loaded once per definition): a shipped model's compiled-in kernels,
// or the lattice code of the user's file compiled at run time. InputError when the file changed
// since it was loaded or this build has no model compiler. Call with the GIL held.
const lrchain_lattice_kernels& lattice_kernels(const LoadedModel& m);

// {"name", "file_hash", "parameters", "lattice_code"} as the CLI's JSON "model" (GIL held).
nlohmann::json model_summary_json(const LoadedModel& m);

}  // namespace lrchain::python
