// The shipped models' definitions, built once from the generated evaluator headers.
#include "lrchain/generated/shipped_models.hpp"
#include "lrchain/model.hpp"

namespace lrchain {

const std::vector<ModelDefinition>& shipped_models() {
  static const std::vector<ModelDefinition> models = generated::shipped_model_definitions();
  return models;
}

}  // namespace lrchain
