#pragma once
// A model definition handed from the run-time model compiler's module (lrchain._model_compiler,
// which links GiNaC and is imported only when a user's model file is loaded) to the main module:
// a capsule owning a heap std::shared_ptr<const ModelDefinition> (or of its lattice kernels).
#include <memory>

#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_abi.h"

namespace lrchain::python {

inline constexpr const char* kModelCapsuleName = "lrchain.ModelDefinition";
using ModelDefinitionHandle = std::shared_ptr<const ModelDefinition>;
// The lattice kernels of a user's model file (lrchain._model_compiler.compile_lattice).
inline constexpr const char* kLatticeCapsuleName = "lrchain.LatticeKernels";
using LatticeKernelsHandle = std::shared_ptr<const lrchain_lattice_kernels>;

}  // namespace lrchain::python
