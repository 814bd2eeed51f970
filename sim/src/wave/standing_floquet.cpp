// Floquet multipliers of a standing wave's period map on a ring (standing_wave.hpp).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <boost/numeric/odeint.hpp>

#include "lrchain/sim/wave/standing_wave.hpp"

namespace lrchain::sim::wave {

StandingFloquet standing_floquet(CompiledLattice& ring, const StandingWave& wave, double tolerance) {
  const Index P = ring.positions(), columns = 2 * P;
  // Y = [X; V], X' = V, V' = J(u(t)) X, column-major 2P x 2P, from the identity.
  std::vector<double> y(std::size_t(columns * columns), 0.0);
  for (Index j = 0; j < columns; ++j) y[std::size_t(j * columns + j)] = 1;
  Eigen::VectorXd q(P);
  const auto variational = [&](const std::vector<double>& s, std::vector<double>& ds, double t) {
    standing_positions(wave, ring.sites(), t, q);
    for (Index j = 0; j < columns; ++j) {
      const double* x = s.data() + j * columns;
      double* dx = ds.data() + j * columns;
      std::copy(x + P, x + 2 * P, dx);
      ring.jacobian_action(q.data(), x, dx + P);
    }
  };
  namespace odeint = boost::numeric::odeint;
  const double period = 2 * std::numbers::pi / wave.omega;
  odeint::integrate_adaptive(odeint::make_controlled<odeint::runge_kutta_dopri5<std::vector<double>>>(1e-11, 1e-11),
                             variational, y, 0.0, period, period / 200);
  const Eigen::Map<const Eigen::MatrixXd> monodromy(y.data(), columns, columns);
  const Eigen::VectorXcd mu = monodromy.eigenvalues();
  StandingFloquet f;
  f.multipliers.assign(mu.data(), mu.data() + mu.size());
  std::sort(f.multipliers.begin(), f.multipliers.end(),
            [](auto a, auto b) { return std::abs(a) > std::abs(b); });
  f.largest_modulus = std::abs(f.multipliers.front());
  f.stable = f.largest_modulus <= 1 + tolerance;
  return f;
}

}  // namespace lrchain::sim::wave
