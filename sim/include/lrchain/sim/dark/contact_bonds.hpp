#pragma once
// The one-sided contacts of a model lattice (docs/dark-models.md): for each bond whose force law
// declares a contact condition, its overlap at site n as a linear function of the lattice variables,
//   s_n = offset + sum_k coefficient_k q[variable_k][n + shift_k]   (periodic in n),
// with the contact lost where s_n < 0. A contact change is a sign change of some s_n.
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/compiled_model_abi.h"

namespace lrchain::sim::dark {

struct ContactBondTerm {
  Index variable = 0;  // field index of the lattice form (strain form: 0 is r, f >= 1 is w_f)
  Index shift = 0;     // site offset from n
  double coefficient = 0;
};

struct ContactBond {
  std::string name;  // for messages, e.g. "F(u[n+1] - u[n])"
  double offset = 0;
  std::vector<ContactBondTerm> terms;
};

using ContactBonds = std::vector<ContactBond>;

// The one-sided contacts of a model's generated lattice code (kernels.strain_contacts for the strain
// form, displacement_contacts otherwise) at `parameters` (the model file's order): each contact bond's
// linear form with its zero coefficients dropped and its lowest shift at 0; bonds with the same linear
// form once. Empty for a smooth model. InputError naming the bond when an overlap is not linear in the
// lattice variables (its sign changes cannot be located).
ContactBonds model_contact_bonds(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters,
                                 bool strain_form);

// Overlaps s_n of every bond (bond-major, `sites` entries each) and their rates at positions q and
// velocities qdot (each fields x sites, field-major).
void contact_overlaps(const ContactBonds& bonds, Index sites, const double* q, const double* qdot, double* overlap,
                      double* rate);

}  // namespace lrchain::sim::dark
