// Exact dark breathers of model files (sim/dark/shooting.hpp) on the models' generated
// lattice kernels: Newton from the NLS seed converges, the orbit closes after one period
// (E_b(T_b) <= 1e-10, eq:relerr), the full-period Floquet multipliers pair as (lambda, 1/lambda)
// (Hamiltonian, reversible flow), and the breather does not depend on the ring's size: on N and
// about 2N sites the profile near the dip agrees. The resonant chain through its model file gives
// the paper's strain-lattice breather (resonant_chain_shooting.hpp) to round-off.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/dark/floquet.hpp"
#include "lrchain/sim/dark/measures.hpp"
#include "lrchain/sim/dark/dark_ansatz.hpp"
#include "lrchain/sim/dark/shooting.hpp"
#include "lrchain/sim/dark/resonant_chain_shooting.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

using namespace lrchain;
using namespace lrchain::sim;
using namespace lrchain::sim::dark;

namespace {

struct DarkSolution {
  Eigen::VectorXd z0;
  int iterations = 0;
  DarkMeasures measures;
  FloquetResult floquet;
  DarkAnsatz ansatz;
};

DarkSolution solve_model(const Model& model, double omega_b, int sites, bool floquet) {
  const lrchain_lattice_kernels& kernels = lattice_kernels_of(model);
  DarkSolution s;
  s.ansatz = make_dark_ansatz(model, kernels, defocusing_edge(model, std::nullopt), omega_b);
  const DarkShooting shooting(kernels, lattice_parameters(model), sites, s.ansatz.mean_flow, ShootingMode::reversible);
  const NewtonResult newton = newton_solve(shooting, dark_seed(s.ansatz, DarkCenter::bond, sites), omega_b, {});
  REQUIRE(newton.converged);
  s.z0 = newton.q;
  s.iterations = int(newton.history.size()) - 1;
  shooting.measure(s.z0, omega_b, s.measures);
  if (floquet) s.floquet = floquet_from_monodromy(shooting.monodromy(s.z0, omega_b));
  return s;
}

// max over variables f and sites k in [-width, width] around the dip of |z_small - z_large|.
double centre_difference(const DarkSolution& small, int n_small, const DarkSolution& large, int n_large, int width) {
  const bool pair = small.ansatz.theta == 0;  // dip at array index N/4 (+ 1/2); else at the centre
  const int c_small = pair ? n_small / 4 : (n_small - 1) / 2, c_large = pair ? n_large / 4 : (n_large - 1) / 2;
  const int fields = int(small.z0.size()) / n_small;
  double d = 0;
  for (int f = 0; f < fields; ++f)
    for (int k = -width; k <= width; ++k)
      d = std::max(d, std::abs(small.z0(f * n_small + c_small + k) - large.z0(f * n_large + c_large + k)));
  return d;
}

struct DarkCase {
  std::string model;
  std::vector<std::pair<std::string, double>> parameters;
  double omega_b;
  int sites, sites_doubled;
  double centre_tolerance;  // N vs doubled ring near the dip (set from the measured difference, see below)
};

void check_case(const DarkCase& k) {
  const Model model = shipped_model(k.model, k.parameters);
  const DarkSolution a = solve_model(model, k.omega_b, k.sites, true);
  const DarkSolution b = solve_model(model, k.omega_b, k.sites_doubled, false);
  const double centre = centre_difference(a, k.sites, b, k.sites_doubled, 5);
  std::printf("dark %s: edge %.10f (theta %s), omega_b %.4f, N %d: %d Newton iterations, E_b(T_b) %.3e, K_x %.6f, "
              "Floquet %s max|lambda| %.8f pairing defect %.2e; N = %d: E_b %.3e, max centre difference %.3e, "
              "K_x %.6f\n",
              k.model.c_str(), a.ansatz.omega, a.ansatz.theta == 0 ? "0" : "pi", k.omega_b, k.sites, a.iterations,
              a.measures.E_b, a.measures.K_x, a.floquet.kind().c_str(), a.floquet.max_modulus, a.floquet.pairing_defect,
              k.sites_doubled, b.measures.E_b, centre, b.measures.K_x);
  CHECK(a.measures.E_b <= 1e-10);  // issue's target for an exact breather (the paper reaches < 3e-9)
  CHECK(b.measures.E_b <= 1e-10);
  // Multipliers of a Hamiltonian flow come in (lambda, 1/conj lambda) pairs; the full-period
  // monodromy does not impose it, so the defect measures the integration (Jordan blocks at +1 of
  // the phase and zero modes split like sqrt(error): 1e-5 seen, 1e-4 allowed).
  CHECK(a.floquet.pairing_defect < 1e-4);
  // Bounded spectrum: the on-site breathers are stable to 1e-6 (max|lambda| - 1 ~ 2e-4 for
  // klein_gordon at N = 61, ~1e-7 for newtons_cradle); the diatomic pair shows a weak real
  // instability (max|lambda| 1.003).
  CHECK(a.floquet.max_modulus < 1.01);
  CHECK(centre < k.centre_tolerance);
}

}  // namespace

TEST_CASE("dark breathers of model files: klein_gordon (b = -1/2, defocusing at theta = pi), N and 2N" *
          doctest::test_suite("validation")) {
  // h = -0.728 < 0 and omega'' = -C/omega < 0 at theta = pi (lrchain coeffs --model ... --set b=-1/2).
  check_case({"klein_gordon", {{"b", -0.5}}, 1.17, 61, 121, 1e-9});  // measured 2.9e-11
}

TEST_CASE("dark breathers of model files: newtons_cradle (defaults, defocusing at theta = pi), N and 2N" *
          doctest::test_suite("validation")) {
  // h = -2.26, omega'' = -0.447 at theta = pi; at omega_b 2.22 the bead amplitude is 0.16, so bond
  // changes stay below 0.33 < delta0: every contact stays closed.
  // Measured 4.0e-7 near the dip: the weakly pinned translation mode (no reflection symmetry is
  // imposed) takes up the integration error, as in the resonant-chain comparison below.
  check_case({"newtons_cradle", {}, 2.22, 101, 201, 1e-5});
}

TEST_CASE("dark breathers of model files: diatomic_chain (optical theta = 0 edge: a pair on an even ring), N and 2N" *
          doctest::test_suite("validation")) {
  // Optical branch at theta = 0: omega = sqrt(3), omega'' = -0.096, h_tilde = -3.70 (theta = pi is singular
  // for this model's coefficients).
  check_case({"diatomic_chain", {}, 1.72, 80, 160, 1e-9});  // measured 3.6e-11
}

TEST_CASE("dark breathers of model files: the resonant chain's model file gives the strain-lattice breather" *
          doctest::test_suite("validation")) {
  // omega_b = 2.445 below omega_opt(pi) = 2.4495: small amplitude, every contact stays closed (the
  // Params path locates contact changes; the model path steps across them).
  const double omega_b = 2.445;
  const int N = 51;
  const Params p;  // alpha 3/2, delta0 4/9, kappa 1, rho 1/3
  const ResonantChainShooting params_shooting(p, N, DarkCenter::bond, ShootingMode::reversible);
  const NewtonResult params_newton = newton_solve(
      params_shooting,
      params_shooting.unknowns_from_z(resonant_chain_dark_seed(make_dark_breather_ansatz(p, Branch::optical, omega_b), DarkCenter::bond, N)),
      omega_b, {});
  REQUIRE(params_newton.converged);
  const Eigen::VectorXd xy = params_shooting.z_from_unknowns(params_newton.q);
  const DarkMeasures params_measures = measure_dark_breather(p, xy, omega_b);

  const Model model = shipped_model("resonant_chain");
  const lrchain_lattice_kernels& kernels = lattice_kernels_of(model);
  const DarkAnsatz ansatz = make_dark_ansatz(model, kernels, defocusing_edge(model, model.branch("optical")), omega_b);
  const DarkShooting shooting(kernels, lattice_parameters(model), N, true, ShootingMode::reversible);
  const NewtonResult newton = newton_solve(shooting, dark_seed(ansatz, DarkCenter::bond, N), omega_b, {});
  REQUIRE(newton.converged);
  DarkMeasures measures;
  shooting.measure(newton.q, omega_b, measures);
  // (r, w) -> (x, y): x_n = r_n, y_n = v_n - v_{n-1} = r_n + w_n - w_{n-1} (periodic).
  double profile = 0;
  for (int n = 0; n < N; ++n) {
    const double y = newton.q(n) + newton.q(N + n) - newton.q(N + (n + N - 1) % N);
    profile = std::max({profile, std::abs(newton.q(n) - xy(n)), std::abs(y - xy(N + n))});
  }
  std::printf("dark resonant_chain model vs Params: omega_b %.4f N %d: max profile difference %.3e, E_b %.3e vs %.3e, "
              "K_x %.15f vs %.15f, max strain %.4f\n",
              omega_b, N, profile, measures.E_b, params_measures.E_b, measures.K_x, params_measures.K_x,
              params_measures.max_strain);
  CHECK(params_measures.max_strain < p.delta0);  // no contact change: both paths integrate the same smooth flow
  // The model path solves for all 2N strains with no reflection symmetry imposed, so the weakly
  // pinned translation mode of the wide dip (a tiny singular value of the shooting Jacobian) takes
  // up the integration error: measured 4.3e-8 here (1.8e-7 with 100x tighter tolerances, so it is
  // conditioning, not accuracy). The amplitude at the far site is not affected: 4e-12 measured.
  CHECK(profile < 1e-6);
  CHECK(std::abs(measures.K_x - params_measures.K_x) < 1e-10);
  CHECK(measures.E_b <= 1e-10);
}
