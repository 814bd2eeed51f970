// Hertzian bond force and energy (eq:Vr), with the alpha = 3/2 loops specialised as s*sqrt(s).
#include "lrchain/sim/contact_law.hpp"

#include <algorithm>
#include <cmath>

namespace lrchain::sim {

ContactLaw make_contact_law(const Params& p) {
  validate(p);
  ContactLaw law;
  law.alpha = p.alpha;
  law.delta0 = p.delta0;
  law.delta0_pow_alpha = std::pow(p.delta0, p.alpha);
  law.delta0_pow_alpha1 = law.delta0_pow_alpha * p.delta0;
  law.three_halves = (p.alpha == 1.5);
  return law;
}

double bond_force(const ContactLaw& law, double r) {
  const double s = std::max(law.delta0 - r, 0.0);
  const double contact = law.three_halves ? s * std::sqrt(s) : std::pow(s, law.alpha);
  return law.delta0_pow_alpha - contact;
}

double bond_energy(const ContactLaw& law, double r) {
  const double s = std::max(law.delta0 - r, 0.0);
  const double contact = law.three_halves ? s * s * std::sqrt(s) : std::pow(s, law.alpha + 1.0);
  return (contact - law.delta0_pow_alpha1) / (law.alpha + 1.0) + law.delta0_pow_alpha * r;
}

namespace {

// The hot loops. s >= 0 always, so __builtin_sqrt needs no errno path and vectorises.
template <bool ThreeHalves>
void forces_strain_loop(const ContactLaw& law, const double* __restrict r, double* __restrict f,
                        std::size_t n) {
  const double d0 = law.delta0, d0a = law.delta0_pow_alpha, alpha = law.alpha;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = std::max(d0 - r[i], 0.0);
    if constexpr (ThreeHalves)
      f[i] = d0a - s * __builtin_sqrt(s);
    else
      f[i] = d0a - std::pow(s, alpha);
  }
}

template <bool ThreeHalves>
void forces_displacement_loop(const ContactLaw& law, const double* __restrict u,
                              double* __restrict f, std::size_t n) {
  const double d0 = law.delta0, d0a = law.delta0_pow_alpha, alpha = law.alpha;
  for (std::size_t i = 0; i < n; ++i) {
    const double s = std::max(d0 - (u[i + 1] - u[i]), 0.0);
    if constexpr (ThreeHalves)
      f[i] = d0a - s * __builtin_sqrt(s);
    else
      f[i] = d0a - std::pow(s, alpha);
  }
}

}  // namespace

void bond_forces_from_strains(const ContactLaw& law, const double* r, double* f, std::size_t n) {
  if (law.three_halves)
    forces_strain_loop<true>(law, r, f, n);
  else
    forces_strain_loop<false>(law, r, f, n);
}

void bond_forces_from_displacements(const ContactLaw& law, const double* u, double* f,
                                    std::size_t n) {
  if (law.three_halves)
    forces_displacement_loop<true>(law, u, f, n);
  else
    forces_displacement_loop<false>(law, u, f, n);
}

}  // namespace lrchain::sim
