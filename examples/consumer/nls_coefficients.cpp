// A tiny program using the installed lrchain library: the NLS coefficients (Sec. 3) of the
// optical branch at theta = pi/2 for the paper's parameters, and the focusing theta-intervals.
#include <cstdio>
#include <numbers>

#include "lrchain/coefficients.hpp"
#include "lrchain/regime/focusing_intervals.hpp"

int main() {
  const lrchain::Params p{1.5, 4.0 / 9.0, 1.0, 1.0 / 3.0};  // alpha, delta0, kappa, rho
  const auto c = lrchain::coefficients(p, lrchain::Branch::optical, std::numbers::pi / 2);
  std::printf("omega = %.10f\nc = %.10f\nomega'' = %.10f\nh_tilde = %.10f\nfocusing = %s\n", c.omega,
              c.group_velocity, c.curvature, c.h_tilde, c.regime == lrchain::Regime::focusing ? "yes" : "no");
  for (const auto& i : lrchain::regime::focusing_intervals(p, lrchain::Branch::optical))
    std::printf("focusing interval: (%.6f, %.6f)\n", i.lo, i.hi);
}
