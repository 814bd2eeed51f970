// Hertzian bond force and energy (eq:Vr), with the alpha = 3/2 loops specialised as s*sqrt(s).
#include "lrchain/sim/contact_law.hpp"

#include "vector_loops.hpp"

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

// The hot loops; for alpha = 3/2 vectorised with packed sqrt (see vector_loops.hpp).
LRCHAIN_SQRT_VECTOR_CLONES
void forces_strain_three_halves(double d0, double d0a, const double* __restrict r,
                                double* __restrict f, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    double s = d0 - r[i];
    s = s > 0.0 ? s : 0.0;
    f[i] = d0a - s * __builtin_sqrt(s);
  }
}

LRCHAIN_SQRT_VECTOR_CLONES
void forces_displacement_three_halves(double d0, double d0a, const double* __restrict u,
                                      double* __restrict f, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    double s = d0 - (u[i + 1] - u[i]);
    s = s > 0.0 ? s : 0.0;
    f[i] = d0a - s * __builtin_sqrt(s);
  }
}

// V(r) = (s^(5/2) - delta0^(5/2))/(5/2) + delta0^(3/2) r, s = (delta0 - r)_+ (eq:Vr, alpha = 3/2);
// the same operations as bond_energy(). In place: r[i] <- V(r[i]).
LRCHAIN_SQRT_VECTOR_CLONES
void energies_strain_three_halves(double d0, double d0a, double d0a1, double* __restrict r,
                                  std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const double x = r[i];
    double s = d0 - x;
    s = s > 0.0 ? s : 0.0;
    r[i] = (s * s * __builtin_sqrt(s) - d0a1) / 2.5 + d0a * x;
  }
}

void forces_strain_general(const ContactLaw& law, const double* __restrict r, double* __restrict f,
                           std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    f[i] = law.delta0_pow_alpha - std::pow(std::max(law.delta0 - r[i], 0.0), law.alpha);
}

void forces_displacement_general(const ContactLaw& law, const double* __restrict u,
                                 double* __restrict f, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i)
    f[i] = law.delta0_pow_alpha -
           std::pow(std::max(law.delta0 - (u[i + 1] - u[i]), 0.0), law.alpha);
}

}  // namespace

void bond_forces_from_strains(const ContactLaw& law, std::span<const double> r, std::span<double> f) {
  if (law.three_halves)
    forces_strain_three_halves(law.delta0, law.delta0_pow_alpha, r.data(), f.data(), r.size());
  else
    forces_strain_general(law, r.data(), f.data(), r.size());
}

void bond_energies_from_strains(const ContactLaw& law, std::span<const double> r, std::span<double> V) {
  const std::size_t n = r.size();
  if (law.three_halves) {
    if (V.data() != r.data()) std::copy(r.begin(), r.end(), V.begin());
    energies_strain_three_halves(law.delta0, law.delta0_pow_alpha, law.delta0_pow_alpha1, V.data(), n);
  } else {
    for (std::size_t i = 0; i < n; ++i) V[i] = bond_energy(law, r[i]);
  }
}

void bond_forces_from_displacements(const ContactLaw& law, std::span<const double> u, std::span<double> f) {
  if (law.three_halves)
    forces_displacement_three_halves(law.delta0, law.delta0_pow_alpha, u.data(), f.data(), f.size());
  else
    forces_displacement_general(law, u.data(), f.data(), f.size());
}

}  // namespace lrchain::sim
