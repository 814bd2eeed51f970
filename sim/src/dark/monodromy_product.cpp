// Monodromy-vector products on the recorded orbit (monodromy_product.hpp).
#include "lrchain/sim/dark/monodromy_product.hpp"

#include <algorithm>
#include <numbers>

#include "lrchain/errors.hpp"

namespace lrchain::sim::dark {

MonodromyProduct::MonodromyProduct(const DarkShooting& shooting, const Eigen::VectorXd& z0, double omega_b)
    : orbit_(shooting.orbit()), z0_(z0), size_(2 * shooting.orbit().positions()), extended_(std::size_t(2 * size_), 0.0) {
  std::vector<double> state(std::size_t(size_), 0.0);
  std::copy(z0.data(), z0.data() + orbit_.positions(), state.begin());
  orbit_.record(state, 0.0, 2.0 * std::numbers::pi / omega_b, steps_);
  if (steps_.size.empty()) throw NumericalFailure("Floquet: the orbit ran away over one period");
}

// y = Phi(T_b) x: [z0, 0 | x] replayed with the orbit over one period.
void MonodromyProduct::apply(const double* x, double* y) const {
  const std::size_t n = std::size_t(size_), P = n / 2;
  std::fill(extended_.begin(), extended_.end(), 0.0);
  std::copy(z0_.data(), z0_.data() + P, extended_.begin());
  std::copy(x, x + n, extended_.begin() + std::ptrdiff_t(n));
  orbit_.replay(steps_, extended_, 1);
  std::copy(extended_.begin() + std::ptrdiff_t(n), extended_.end(), y);
  ++products_;
}

}  // namespace lrchain::sim::dark
