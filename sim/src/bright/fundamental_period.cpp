// Whether a bright breather oscillates at omega_b or at a multiple (fundamental_period.hpp).
#include "lrchain/sim/bright/fundamental_period.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include <fmt/format.h>

namespace lrchain::sim::bright {

Index interior_turning_points(const dark::DarkOrbit& orbit, const Eigen::VectorXd& z0, double omega_b, Index samples) {
  const Index positions = orbit.positions();
  Index peak = 0;
  z0.head(orbit.sites()).cwiseAbs().maxCoeff(&peak);
  std::vector<double> state(std::size_t(2 * positions), 0.0);
  for (Index i = 0; i < positions; ++i) state[std::size_t(i)] = z0(i);
  const double half = std::numbers::pi / omega_b;
  std::vector<double> velocity;
  double largest = 0;
  for (Index k = 1; k < samples; ++k) {  // t in (0, T_b/2), both ends excluded
    orbit.integrate(state, half * double(k - 1) / double(samples), half * double(k) / double(samples));
    velocity.push_back(state[std::size_t(positions + peak)]);
    largest = std::max(largest, std::abs(velocity.back()));
  }
  Index turns = 0;
  int sign = 0;
  for (const double v : velocity) {
    if (std::abs(v) <= 1e-6 * largest) continue;
    const int s = v > 0 ? 1 : -1;
    turns += sign != 0 && s != sign;
    sign = s;
  }
  return turns;
}

std::string fundamental_period_reason(const dark::DarkOrbit& orbit, const Eigen::VectorXd& z0, double omega_b) {
  const Index turns = interior_turning_points(orbit, z0, omega_b);
  if (turns == 0) return "";
  return fmt::format("its peak site turns {} times inside half a period: an orbit of frequency {} omega_b, not a "
                     "breather at omega_b (the shooting condition holds for both)",
                     turns, turns + 1);
}

}  // namespace lrchain::sim::bright
