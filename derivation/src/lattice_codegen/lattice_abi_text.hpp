#pragma once
// Fixed text of every generated lattice source: the kernel table (the text of
// lib/include/lrchain/compiled_model_abi.h, embedded at configure time), the power helpers and
// the padded workspace.
#include <string>

namespace lrchain::derivation {

std::string lattice_abi_text();
std::string helpers_text();
std::string workspace_text();  // needs kPad, kVariables, kBonds, kBondPad defined before it

}  // namespace lrchain::derivation
