#pragma once
// The one-sided contacts of a model lattice (docs/dark-models.md): for each bond whose force law
// declares a contact condition, its overlap at site n as a linear function of the lattice variables,
//   s_n = offset + sum_k coefficient_k q[variable_k][n + shift_k]   (periodic in n),
// with the contact lost where s_n < 0. A contact change is a sign change of some s_n.
#include <string>
#include <vector>

namespace lrchain::sim::dark {

struct ContactBondTerm {
  int variable = 0;  // field index of the lattice form (strain form: 0 is r, f >= 1 is w_f)
  int shift = 0;     // site offset from n
  double coefficient = 0;
};

struct ContactBond {
  std::string name;  // for messages, e.g. "F(u[n+1] - u[n])"
  double offset = 0;
  std::vector<ContactBondTerm> terms;
};

using ContactBonds = std::vector<ContactBond>;

// Overlaps s_n of every bond (bond-major, `sites` entries each) and their rates at positions q and
// velocities qdot (each fields x sites, field-major).
void contact_overlaps(const ContactBonds& bonds, int sites, const double* q, const double* qdot, double* overlap,
                      double* rate);

}  // namespace lrchain::sim::dark
