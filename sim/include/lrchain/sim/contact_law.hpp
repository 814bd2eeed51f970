#pragma once
// Hertzian contact law of the chain: the bond force V'(r) = delta0^alpha - (delta0 - r)_+^alpha and
// the bond energy V(r) (eq:Vr), evaluated exactly (contact loss included) for any alpha > 1.
#include <span>

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

// f[i] = V'(r[i]) for i < r.size() (f has at least as many entries; one sqrt per bond when
// alpha = 3/2). No allocation.
void bond_forces_from_strains(const ContactLaw& law, std::span<const double> r, std::span<double> f);
// V[i] = V(r[i]) for i < r.size() (eq:Vr; one sqrt per bond when alpha = 3/2); V may be r. No
// allocation.
void bond_energies_from_strains(const ContactLaw& law, std::span<const double> r, std::span<double> V);
// f[i] = V'(u[i+1] - u[i]) for i < f.size() (reads u[0..f.size()], so u has one entry more). No
// allocation.
void bond_forces_from_displacements(const ContactLaw& law, std::span<const double> u, std::span<double> f);

}  // namespace lrchain::sim
