// The generated kernels of the shipped models (generated/*.cpp, from models/*.toml).
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lrchain/sim/model_lattice.hpp"

extern "C" {
const lrchain_lattice_kernels* lrchain_lattice_resonant_chain(void);
const lrchain_lattice_kernels* lrchain_lattice_homogeneous_chain(void);
const lrchain_lattice_kernels* lrchain_lattice_fput(void);
const lrchain_lattice_kernels* lrchain_lattice_klein_gordon(void);
const lrchain_lattice_kernels* lrchain_lattice_newtons_cradle(void);
const lrchain_lattice_kernels* lrchain_lattice_diatomic_chain(void);
const lrchain_lattice_kernels* lrchain_lattice_resonant_chain_polynomial(void);
}

namespace lrchain::sim {

namespace {
const std::vector<std::pair<std::string_view, const lrchain_lattice_kernels* (*)()>>& table() {
  static const std::vector<std::pair<std::string_view, const lrchain_lattice_kernels* (*)()>> t{
      {"resonant_chain", lrchain_lattice_resonant_chain},
      {"homogeneous_chain", lrchain_lattice_homogeneous_chain},
      {"fput", lrchain_lattice_fput},
      {"klein_gordon", lrchain_lattice_klein_gordon},
      {"newtons_cradle", lrchain_lattice_newtons_cradle},
      {"diatomic_chain", lrchain_lattice_diatomic_chain},
      {"resonant_chain_polynomial", lrchain_lattice_resonant_chain_polynomial}};
  return t;
}
}  // namespace

const lrchain_lattice_kernels* shipped_lattice_kernels(std::string_view model_name) {
  for (const auto& [name, entry] : table())
    if (name == model_name) return entry();
  return nullptr;
}

std::vector<std::string> shipped_lattice_models() {
  std::vector<std::string> names;
  for (const auto& [name, entry] : table()) names.emplace_back(name);
  return names;
}

}  // namespace lrchain::sim
