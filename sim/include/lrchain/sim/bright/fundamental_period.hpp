#pragma once
// Whether a converged shooting solution oscillates at omega_b or at a multiple of it. The reversible
// shooting condition Zdot(T_b/2) = 0 also holds for an orbit of frequency k omega_b (k half-turns of
// the peak site in half a period), e.g. a large-amplitude breather of a hard on-site potential whose
// own frequency is 10 omega_b: a localized zero of Newton that is no breather at omega_b.
#include <string>

#include <Eigen/Dense>

#include "lrchain/sim/dark/shooting.hpp"

namespace lrchain::sim::bright {

// The turning points of the peak site's first variable (|z0| largest) strictly inside (0, T_b/2), from
// `samples` steps of the orbit of [z0, 0]: 0 for an orbit of frequency omega_b (it turns at 0 and at
// T_b/2 only), k - 1 for one of frequency k omega_b. A velocity below 1e-6 of its largest counts as 0.
Index interior_turning_points(const dark::DarkOrbit& orbit, const Eigen::VectorXd& z0, double omega_b, Index samples = 128);

// "" when the orbit turns only at 0 and T_b/2, else why it is no breather at omega_b.
std::string fundamental_period_reason(const dark::DarkOrbit& orbit, const Eigen::VectorXd& z0, double omega_b);

}  // namespace lrchain::sim::bright
