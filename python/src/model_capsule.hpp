#pragma once
// What passes between the main module and the run-time model compiler's module
// (lrchain._model_compiler, which links GiNaC and is imported only when a user's model file must be
// compiled): the model file as the loader read it (a capsule borrowing a ModelFileContent), and back
// a capsule owning a heap std::shared_ptr<const ModelDefinition> (or of its lattice kernels).
#include <memory>

#include "lrchain/model.hpp"
#include "lrchain/compiled_model_abi.h"

namespace lrchain::python {

// The model file read by jobs::ModelSource (borrowed for the duration of the call).
inline constexpr const char* kModelFileCapsuleName = "lrchain.ModelFileContent";
inline constexpr const char* kModelCapsuleName = "lrchain.ModelDefinition";
using ModelDefinitionHandle = std::shared_ptr<const ModelDefinition>;
// The lattice kernels of a user's model file (lrchain._model_compiler.compile_lattice).
inline constexpr const char* kLatticeCapsuleName = "lrchain.LatticeKernels";
using LatticeKernelsHandle = std::shared_ptr<const lrchain_lattice_kernels>;

}  // namespace lrchain::python
