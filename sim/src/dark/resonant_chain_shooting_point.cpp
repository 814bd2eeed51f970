// Floquet multipliers and measures of a converged point of the resonant chain's shooting
// (resonant_chain_shooting.hpp), as the continuation asks for them (Sec. 5.3-5.4).
#include "lrchain/sim/dark/floquet.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"

namespace lrchain::sim::dark {

// Reversible mode: floquet_reversible on the shooting propagator; full mode: the monodromy.
void ResonantChainShooting::jacobian_and_floquet(const Eigen::VectorXd& q, double omega_b, Eigen::VectorXd& r,
                                        Eigen::MatrixXd& J, FloquetResult* floquet) const {
  Eigen::MatrixXd Phi;
  if (floquet && mode_ == ShootingMode::reversible) {
    evaluate(q, omega_b, r, &J, &Phi);
    *floquet = floquet_reversible(*this, Phi);
  } else {
    evaluate(q, omega_b, r, &J);
    if (floquet) {  // full mode: the propagator is the monodromy
      evaluate(q, omega_b, r, &J, &Phi);
      *floquet = floquet_from_monodromy(Phi);
    }
  }
}

void ResonantChainShooting::measure(const Eigen::VectorXd& z0, double omega_b, DarkMeasures& out) const {
  out = measure_dark_breather(p_, z0, omega_b, integration_);
}

}  // namespace lrchain::sim::dark
