// The installed simulator used from another project: an exact dark breather of the paper's chain
// (Sec. 5.3, bond-centred, optical band edge, omega_b = 2.42) by shooting Newton, and a short
// bright-breather run (Sec. 4.1, optical branch, theta = pi/2) compared with its NLS ansatz.
#include <cstdio>
#include <numbers>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"

int main() {
  namespace dark = lrchain::sim::dark;
  const lrchain::Params p;  // alpha 3/2, delta0 4/9, kappa 1, rho 1/3
  const double omega_b = 2.42;
  const lrchain::Index sites = 41;
  const auto ansatz = lrchain::make_dark_breather_ansatz(p, lrchain::Branch::optical, omega_b);
  const dark::ResonantChainShooting shooting(p, sites, lrchain::DarkCenter::bond, dark::ShootingMode::reversible);
  const auto seed = shooting.unknowns_from_z(dark::resonant_chain_dark_seed(ansatz, lrchain::DarkCenter::bond, sites));
  const auto solved = dark::newton_solve(shooting, seed, omega_b, {});
  const auto m = dark::measure_dark_breather(p, shooting.z_from_unknowns(solved.q), omega_b);
  std::printf("dark: converged = %s, Newton iterations = %zu, E_b = %.1e, K_x = %.4f\n",
              solved.converged ? "yes" : "no", solved.history.size(), m.E_b, m.K_x);

  lrchain::sim::BrightRunConfig bright;  // defaults: N = 500, srkn11b at an automatic step
  bright.theta = std::numbers::pi / 2;
  bright.periods = 20;
  bright.snapshot_periods = {};
  const auto run = lrchain::sim::run_resonant_chain_bright(bright);
  std::printf("bright: max E_x = %.4f over %.0f T_b, energy drift = %.1e\n", run.summary.max_Ex,
              bright.periods, run.summary.max_energy_drift);
}
