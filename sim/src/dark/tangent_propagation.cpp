#include "lrchain/sim/dark/tangent_propagation.hpp"

#include <algorithm>
#include <csignal>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include <stdexcept>
#include <vector>

#include "lrchain/errors.hpp"

namespace lrchain::sim::dark {

void propagate_tangents(const StrainLatticeOrbit& orbit, const OrbitRecord& record,
                        Eigen::MatrixXd& phi, Index block, const std::atomic<bool>* stop) {
  using State = std::vector<double>;
  const Index N = orbit.sites();
  const Index rows = 4 * N;
  if (phi.rows() != rows) throw std::invalid_argument("propagate_tangents: phi must have 4N rows");
  if (record.steps() == 0 || phi.cols() == 0) return;
  if (block < 1) throw std::invalid_argument("propagate_tangents: block must be >= 1");
  const Index m = phi.cols();
  const Index blocks = (m + block - 1) / block;
  const double kappa = orbit.params().kappa;
  const double kor = orbit.params().kappa / orbit.params().rho;
  bool stage_mismatch = false;
  std::atomic<bool> interrupted{false};

#pragma omp parallel
  {
    State s;
#pragma omp for schedule(dynamic, 1)
    for (Index bi = 0; bi < blocks; ++bi) {
      const Index c0 = bi * block;
      const Index b = std::min(block, m - c0);
      // One stepper per block: Odeint sizes its stage storage on first use (blocks differ in size).
      boost::numeric::odeint::runge_kutta_fehlberg78<State> stepper;
      s.assign(static_cast<std::size_t>(rows * b), 0.0);
      for (Index j = 0; j < b; ++j)
        for (Index r = 0; r < rows; ++r) s[static_cast<std::size_t>(r * b + j)] = phi(r, c0 + j);
      Index step = 0;
      Index call = 0;
      auto sys = [&](const State& x, State& dx, double) {
        const double* g = record.stage(step, std::min(call, OrbitRecord::stages - 1));
        ++call;
        tangent_block_rhs(N, b, kappa, kor, g, x.data(), dx.data());
      };
      for (step = 0; step < record.steps(); ++step) {
        if (stop && stop->load(std::memory_order_relaxed)) {
          interrupted = true;
          break;
        }
        call = 0;
        stepper.do_step(sys, s, record.t[static_cast<std::size_t>(step)], record.dt[static_cast<std::size_t>(step)]);
        if (call != OrbitRecord::stages) stage_mismatch = true;
      }
      for (Index j = 0; j < b; ++j)
        for (Index r = 0; r < rows; ++r) phi(r, c0 + j) = s[static_cast<std::size_t>(r * b + j)];
    }
  }
  if (interrupted) throw Interrupted(SIGINT, "interrupted by SIGINT");
  if (stage_mismatch) throw std::logic_error("propagate_tangents: stage count mismatch in replay");
}

}  // namespace lrchain::sim::dark
