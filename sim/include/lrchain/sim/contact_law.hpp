#pragma once
// Hertzian contact law of the chain: the bond force V'(r) = delta0^alpha - (delta0 - r)_+^alpha and
// the bond energy V(r) (eq:Vr), evaluated exactly (contact loss included) for any alpha > 1.
#include <cstddef>

#include "lrchain/params.hpp"

namespace lrchain::sim {

// Precomputed constants of eq:Vr for one parameter set.
struct ContactLaw {
  double alpha = 1.5;
  double delta0 = 4.0 / 9.0;
  double delta0_pow_alpha = 0;     // delta0^alpha (the precompression force)
  double delta0_pow_alpha1 = 0;    // delta0^(alpha+1)
  bool three_halves = true;        // alpha == 3/2: (.)^(3/2) evaluated as s*sqrt(s)
};

// Throws InvalidParameter if p is invalid.
ContactLaw make_contact_law(const Params& p);

// V'(r) for one bond (derivative of eq:Vr).
double bond_force(const ContactLaw& law, double r);
// V(r) for one bond (eq:Vr); V(0) = V'(0) = 0.
double bond_energy(const ContactLaw& law, double r);

// f[i] = V'(r[i]) for i < n (one sqrt per bond when alpha = 3/2). No allocation.
void bond_forces_from_strains(const ContactLaw& law, const double* r, double* f, std::size_t n);
// V[i] = V(r[i]) for i < n (eq:Vr; one sqrt per bond when alpha = 3/2); V may be r. No allocation.
void bond_energies_from_strains(const ContactLaw& law, const double* r, double* V, std::size_t n);
// f[i] = V'(u[i+1] - u[i]) for i < n (reads u[0..n]). No allocation.
void bond_forces_from_displacements(const ContactLaw& law, const double* u, double* f,
                                    std::size_t n);

}  // namespace lrchain::sim
