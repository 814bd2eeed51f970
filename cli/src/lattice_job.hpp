#pragma once
// The lattice of a job that runs on a model's generated kernels (bright, wave): the loaded model's
// kernels set into the job's Config, then the job's validate() with its keys renamed to the command's
// options.
#include <vector>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/option_schema.hpp"
#include "model_option.hpp"

namespace lrchain::cli {

// `model` (alive while `config` is used) and its lattice kernels into `config`; validate(config), an
// InvalidParameter renamed to its option in `options`. The returned code keeps a run-time compiled
// library loaded.
template <class Config>
LatticeCode validated_lattice_job(Config& config, const Model& model, const ModelSelection& selection,
                                  const std::vector<jobs::JobOption>& options) {
  LatticeCode code = lattice_kernels_for(selection, model);
  config.model = &model;
  config.kernels = code.kernels.get();
  try {
    validate(config);
  } catch (const InvalidParameter& e) {
    throw jobs::renamed_parameter(e, jobs::cli_name(options, e.parameter()));
  }
  return code;
}

}  // namespace lrchain::cli
