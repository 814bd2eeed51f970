#pragma once
// Lattice code from a model file: one self-contained C++ translation unit with the exact
// accelerations of every field (one-sided contact applied), their Jacobian action and the energy
// density, behind one extern "C" entry point `lrchain_lattice_<name>` returning a table of
// function pointers (the layout of docs/simulator.md, lib/include/lrchain/compiled_model_abi.h).
#include <string>

#include "lrchain/derivation/model_file.hpp"

namespace lrchain::derivation {

// The C++ source; throws lrchain::InputError when the model's force laws cannot be simulated
// (a force not linear in its function calls, a contact condition not linear in the argument).
std::string lattice_source(const ModelFile& model);

}  // namespace lrchain::derivation
