#pragma once
// The monodromy-vector product y = M x of a breather of any model lattice (shooting.hpp) without the
// matrix: the orbit from [z0, 0] recorded once over one period T_b, then each product one tangent
// replayed with it on the recorded steps (the derivative of the discrete flow). Shared by the Arnoldi
// multipliers (krylov_floquet.hpp) and the full-lattice residuals of windowed multipliers
// (bright/windowed_floquet.hpp).
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/dark/shooting.hpp"

namespace lrchain::sim::dark {

class MonodromyProduct {
 public:
  // Records the orbit; throws NumericalFailure when it runs away within the period.
  MonodromyProduct(const DarkShooting& shooting, const Eigen::VectorXd& z0, double omega_b);
  Index size() const { return size_; }  // 2 positions()
  // y = M x (x, y: size() entries each).
  void apply(const double* x, double* y) const;
  Index products() const { return products_; }

 private:
  const DarkOrbit& orbit_;
  Eigen::VectorXd z0_;
  DarkOrbit::RecordedSteps steps_;
  Index size_;
  mutable std::vector<double> extended_;
  mutable Index products_ = 0;
};

}  // namespace lrchain::sim::dark
