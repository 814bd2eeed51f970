// Overlaps of a model lattice's one-sided contacts (contact_bonds.hpp).
#include "lrchain/sim/dark/contact_bonds.hpp"

#include <algorithm>
#include <cstddef>
#include <stdexcept>

#include "lrchain/errors.hpp"

namespace lrchain::sim::dark {

// s_n = offset + sum_k c_k q[v_k][n + shift_k] on a periodic ring, and ds_n/dt from qdot.
void contact_overlaps(const ContactBonds& bonds, Index sites, const double* q, const double* qdot, double* overlap,
                      double* rate) {
  const Index N = sites;
  for (std::size_t j = 0; j < bonds.size(); ++j) {
    double* s = overlap + Index(j) * N;
    double* ds = rate + Index(j) * N;
    for (Index n = 0; n < N; ++n) {
      s[n] = bonds[j].offset;
      ds[n] = 0.0;
    }
    for (const auto& term : bonds[j].terms) {
      const Index base = term.variable * N;
      const Index shift = (term.shift % N + N) % N;
      for (Index n = 0; n < N; ++n) {
        const Index at = base + (n + shift) % N;
        s[n] += term.coefficient * q[at];
        ds[n] += term.coefficient * qdot[at];
      }
    }
  }
}

// The contact table of the generated kernels (lrchain/compiled_model_abi.h) evaluated at the parameters.
ContactBonds model_contact_bonds(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                 bool strain_form) {
  if (parameters.size() != std::size_t(kernels.parameter_count))
    throw std::invalid_argument("model_contact_bonds: the kernels of " + std::string(kernels.model_name) + " take " +
                                std::to_string(kernels.parameter_count) + " parameters");
  const lrchain_lattice_contacts* table = strain_form ? kernels.strain_contacts : kernels.displacement_contacts;
  if (!table) return {};
  std::size_t total = 0;
  for (int j = 0; j < table->bonds; ++j) total += std::size_t(std::max(table->term_counts[j], 0));
  std::vector<double> offsets(std::size_t(table->bonds)), coefficients(std::max<std::size_t>(total, 1));
  table->forms(parameters.data(), offsets.data(), coefficients.data());
  ContactBonds bonds;
  std::size_t t = 0;
  for (int j = 0; j < table->bonds; ++j) {
    if (table->term_counts[j] < 0)
      throw InputError("model " + std::string(kernels.model_name) + ": contact bond " + table->names[j] +
                       ": locating contact changes needs an overlap linear in the lattice variables");
    ContactBond bond{table->names[j], offsets[std::size_t(j)], {}};
    for (int k = 0; k < table->term_counts[j]; ++k, ++t)
      if (coefficients[t] != 0.0) bond.terms.push_back({Index{table->variables[t]}, Index{table->shifts[t]}, coefficients[t]});
    if (bond.terms.empty()) continue;  // a constant overlap never changes sign
    Index lowest = bond.terms.front().shift;
    for (const auto& term : bond.terms) lowest = std::min(lowest, term.shift);
    for (auto& term : bond.terms) term.shift -= lowest;
    const bool known = std::any_of(bonds.begin(), bonds.end(), [&](const ContactBond& b) {
      return b.offset == bond.offset &&
             std::equal(b.terms.begin(), b.terms.end(), bond.terms.begin(), bond.terms.end(),
                        [](const ContactBondTerm& x, const ContactBondTerm& y) {
                          return x.variable == y.variable && x.shift == y.shift && x.coefficient == y.coefficient;
                        });
    });
    if (!known) bonds.push_back(std::move(bond));
  }
  return bonds;
}

}  // namespace lrchain::sim::dark
