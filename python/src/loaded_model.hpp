#pragma once
// lrchain.Model as C++: a model loaded by the model loader (jobs::ModelSource: a shipped model, or a
// user's file compiled through lrchain._model_compiler) with parameter values. Copies made by
// replace() share the source, so the lattice kernels are loaded once per loaded file.
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/model_source.hpp"
#include "lrchain/model.hpp"

namespace lrchain::python {

struct LoadedModel {
  std::shared_ptr<const jobs::ModelSource> source;
  Model model;
  const ModelDefinition& definition() const { return *source->definition(); }
};

// The lattice kernels of `m` (loaded once per source): a shipped model's compiled-in kernels, or the
// lattice code of the user's file (the bytes load_model read) compiled at run time. InputError when
// this build has no model compiler. Call with the GIL held.
const lrchain_lattice_kernels& lattice_kernels(const LoadedModel& m);

// {"name", "file_hash", "parameters", "lattice_code"} as the CLI's JSON "model" (GIL held).
nlohmann::json model_summary_json(const LoadedModel& m);

}  // namespace lrchain::python
