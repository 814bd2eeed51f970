#include "lrchain/derivation/evaluate.hpp"

#include <cmath>
#include <stdexcept>

namespace lrchain::derivation {

using namespace GiNaC;

numeric exact(double x) {
  int e = 0;
  const double m = std::frexp(x, &e);                 // x = m 2^e, 0.5 <= |m| < 1
  const auto mant = static_cast<long long>(std::ldexp(m, 53));  // exact 53-bit integer
  numeric r = numeric(mant);
  const int shift = e - 53;
  return shift >= 0 ? r * numeric(2).power(shift) : r / numeric(2).power(-shift);
}

PrecisePoint::PrecisePoint(const DerivedCoefficients& d, const Symbols& s, const PointInput& in, int digits) {
  Digits = digits;
  const numeric a = exact(in.alpha), d0 = exact(in.delta0), th = exact(in.theta);
  // (expv): K2 = a d0^(a-1), K3 = -a(a-1) d0^(a-2)/2, K4 = a(a-1)(a-2) d0^(a-3)/6.
  const numeric p3 = ex_to<numeric>(evalf(pow(d0, a - 3)));
  subs_[s.K2] = a * p3 * d0 * d0;
  subs_[s.K3] = -a * (a - 1) * p3 * d0 / 2;
  subs_[s.K4] = a * (a - 1) * (a - 2) * p3 / 6;
  subs_[s.kappa] = exact(in.kappa);
  subs_[s.rho] = exact(in.rho);
  const numeric sh = ex_to<numeric>(evalf(sin(th / 2)));
  subs_[s.D1] = 4 * sh * sh;
  subs_[s.sigma] = ex_to<numeric>(evalf(sin(th)));
  // omega^2: root of the derived dispersion relation, a polynomial of degree <= 2 in omega^2.
  const realsymbol w2("w2");
  const ex F = expand(d.dispersion.subs(subs_).subs(s.omega == sqrt(w2)));
  const numeric c2 = ex_to<numeric>(evalf(F.coeff(w2, 2))), c1 = ex_to<numeric>(evalf(F.coeff(w2, 1))),
                c0 = ex_to<numeric>(evalf(F.coeff(w2, 0)));
  numeric root;
  if (c2.is_zero()) {
    root = -c0 / c1;
  } else {
    const numeric disc = ex_to<numeric>(evalf(sqrt(c1 * c1 - 4 * c2 * c0)));
    const numeric r1 = (-c1 + disc) / (2 * c2), r2 = (-c1 - disc) / (2 * c2);
    root = (in.optical == (r1 > r2)) ? r1 : r2;
  }
  if (root.is_negative()) throw std::runtime_error("negative omega^2 at evaluation point");
  subs_[s.omega] = ex_to<numeric>(evalf(sqrt(root)));
  subs_[s.c] = value(d.group_velocity);
  subs_[s.gamma] = value(d.gamma);
}

numeric PrecisePoint::value(const ex& e) const {
  const ex v = evalf(e.subs(subs_, subs_options::no_pattern));
  if (!is_a<numeric>(v)) throw std::runtime_error("expression did not evaluate to a number");
  return ex_to<numeric>(v);
}

}  // namespace lrchain::derivation
