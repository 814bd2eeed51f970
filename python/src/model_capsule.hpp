#pragma once
// A model definition handed from the run-time model compiler's module (lrchain._model_compiler,
// which links GiNaC and is imported only when a user's model file is loaded) to the main module:
// a capsule owning a heap std::shared_ptr<const ModelDefinition>.
#include <memory>

#include "lrchain/model.hpp"

namespace lrchain::python {

inline constexpr const char* kModelCapsuleName = "lrchain.ModelDefinition";
using ModelDefinitionHandle = std::shared_ptr<const ModelDefinition>;

}  // namespace lrchain::python
