#include <cmath>
#include <sstream>

#include "lrchain/derivation/derivation_stop.hpp"
#include "lrchain/derivation/model_derivation.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

constexpr double kTolerance = 1e-25;  // relative, at 40 digits
const std::vector<double> kThetas{0.3, 0.7, 1.1, 1.6, 2.1, 2.6, 3.0};

std::string number(double v) {
  std::ostringstream os;
  os.precision(3);
  os << v;
  return os.str();
}

// Largest relative difference of pairs (a, b) over the sample thetas on every real branch.
double max_difference(const ModelDerivation& m, const Symbols& s, const std::vector<std::pair<ex, ex>>& pairs,
                      const DerivedCoefficients* other = nullptr) {
  double worst = 0;
  for (std::size_t b = 0; b < m.branches.size(); ++b) {
    if (!m.branches[b].real) continue;
    for (double theta : kThetas) {
      poll_derivation_stop();
      const BranchPoint p(m.coefficients, s, m.values, theta, b);
      // `other`'s c and gamma at the same point (a re-derivation names them the same symbols).
      exmap other_subs;
      if (other) {
        other_subs = p.substitutions();
        other_subs[s.c] = evalf(other->group_velocity.subs(other_subs, subs_options::no_pattern));
        other_subs[s.gamma] = evalf(other->gamma.subs(other_subs, subs_options::no_pattern));
      }
      for (const auto& [a, bx] : pairs) {
        const numeric va = p.value(a);
        const numeric vb = other ? ex_to<numeric>(evalf(bx.subs(other_subs, subs_options::no_pattern))).real() : p.value(bx);
        const double diff = abs(va - vb).to_double(), scale = (abs(va) + abs(vb)).to_double();
        worst = std::max(worst, scale > 1e-30 ? diff / scale : diff);
      }
    }
  }
  return worst;
}

CheckResult numeric_check(const std::string& name, double worst, int points) {
  return {name, worst <= kTolerance, "numeric, " + std::to_string(points) + " points per real branch, 40 digits",
          "max relative difference " + number(worst)};
}

}  // namespace

std::vector<CheckResult> run_model_checks(const ModelDerivation& m, const Symbols& s) {
  const DerivedCoefficients& d = m.coefficients;
  std::vector<CheckResult> out;
  const int points = int(kThetas.size());
  // c = d omega/d theta and omega'' by implicit differentiation of det M(theta, omega) = 0, with
  // d D1/d theta = 2 sigma and d sigma/d theta = cos theta = 1 - D1/2.
  const auto d_theta = [&](const ex& e) { return e.diff(s.D1) * 2 * s.sigma + e.diff(s.sigma) * (1 - s.D1 / 2); };
  const ex F = numer(normal(d.dispersion));
  const ex omega_prime = -d_theta(F) / F.diff(s.omega);
  const ex omega_second = d_theta(omega_prime) + omega_prime.diff(s.omega) * omega_prime;
  out.push_back(numeric_check("c = d omega/d theta (implicit differentiation of det M = 0)",
                              max_difference(m, s, {{d.group_velocity, omega_prime}}), points));
  out.push_back(numeric_check("omega'' = d^2 omega/d theta^2 (implicit differentiation of det M = 0)",
                              max_difference(m, s, {{explicit_form(d, s, s.gamma * d.curvature_over_gamma), omega_second}}), points));
  for (const ex& v : d.vanishing_modulo_dispersion)
    out.push_back(numeric_check("coefficient of d_xi A_{2,1} vanishes once c is the group velocity",
                                max_difference(m, s, {{v, 0}}), points));
  // The left kernel rescaled by (3 + D1)/2 (theta-dependent): the NLS coefficients must not change.
  {
    const DerivedCoefficients scaled = derive(m.file.model, s, (3 + s.D1) / 2);
    std::vector<std::pair<ex, ex>> pairs{{d.group_velocity, scaled.group_velocity},
                                         {d.curvature, scaled.curvature},
                                         {d.beta, scaled.beta},
                                         {d.h, scaled.h},
                                         {d.lambda, scaled.lambda},
                                         {d.h_tilde, scaled.h_tilde}};
    out.push_back(numeric_check("c, omega'', beta, h, lambda, h_tilde unchanged when the left kernel is rescaled by (3 + D1)/2",
                                max_difference(m, s, pairs, &scaled), points));
  }
  // The right kernel rescaled: with the second field first, the amplitude is B = r A (r = the
  // kernel's second entry, complex and theta-dependent), so c and omega'' are unchanged and
  // h, h_tilde, beta lambda pick up |r|^2 (i A_tau - h |A|^2 A = 0 with B = r A).
  if (m.file.model.fields.size() >= 2) {
    LatticeDescription swapped = m.file.model;
    std::swap(swapped.fields[0], swapped.fields[1]);
    std::swap(swapped.inertia[0], swapped.inertia[1]);
    std::swap(swapped.rhs[0], swapped.rhs[1]);
    std::swap(swapped.shifted[0], swapped.shifted[1]);
    const DerivedCoefficients b = derive(swapped, s);
    const ex r2 = d.kernel[1] * d.kernel[1].conjugate();  // |r|^2 (parameters and omega are real symbols)
    std::vector<std::pair<ex, ex>> pairs{{d.group_velocity, b.group_velocity},
                                         {d.curvature, b.curvature},
                                         {d.h, r2 * b.h},
                                         {d.h_tilde, r2 * b.h_tilde},
                                         {d.beta * d.lambda, r2 * b.beta * b.lambda}};
    out.push_back(numeric_check("c, omega'', h/|r|^2, h_tilde/|r|^2, beta lambda/|r|^2 unchanged when the right kernel is "
                                "rescaled by its second entry r (amplitude carried by field " + swapped.fields[0] + ")",
                                max_difference(m, s, pairs, &b), points));
  }
  // Every coefficient real: coefficient - conj(coefficient) = 0, where normal() alone does not show it
  // after D1 = 4t^2/(1+t^2), sigma = 2t/(1+t^2) (t = tan(theta/2), so sigma^2 = D1 - D1^2/4 exactly).
  {
    const realsymbol t("t");
    bool real = true;
    for (const ex& difference : d.imaginary_parts)
      real &= normal(difference.subs(lst{s.D1 == 4 * t * t / (1 + t * t), s.sigma == 2 * t / (1 + t * t)})).is_zero();
    out.push_back({"every coefficient is real (invariant under complex conjugation)", real, "symbolic",
                   d.imaginary_parts.empty() ? "normal(e - conj(e)) = 0"
                                             : std::to_string(d.imaginary_parts.size()) + " coefficient(s) need sigma^2 = D1 - D1^2/4: " +
                                                   (real ? "then 0" : "not 0")});
  }
  for (auto& r : reference_checks(m, s)) out.push_back(std::move(r));
  return out;
}

}  // namespace lrchain::derivation
