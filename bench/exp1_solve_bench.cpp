// Whole-solve cost of experiment 1 (Sec. 4.2: optical theta = pi/2, rho = 1/3, N = 500, 200 T_b)
// from examples/exp1_optical_pi2.toml, for the issue-4 speed target (>= 50x faster than SciPy
// solve_ivp DOP853 rtol 1e-10 with a NumPy RHS: 2.6-3.9 s). Two numbers per stepper:
//   Exp1Integrate  lattice integration only, observed at the same times with an empty observer
//                  (what the SciPy timing measures);
//   Exp1Run        run_resonant_chain_bright as the CLI runs it: E_x, E_y, energy, e_n, X(t) at every sample.
// Counters: RHS (force) evaluations and ns per site per evaluation (integration cost / (evals*sites)).
#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "lrchain/ansatz/bright_breather.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/jobs/experiment_config.hpp"
#include "lrchain/sim/integrator.hpp"

using namespace lrchain;
using namespace lrchain::sim;
using namespace lrchain::jobs;

namespace {

BrightRunConfig exp1_config() {
  // CMake compiles this file by its absolute path: the examples are next to bench/.
  const auto root = std::filesystem::path(__FILE__).parent_path().parent_path();
  return load_experiment_config(root / "examples" / "exp1_optical_pi2.toml").bright;
}

IntegratorOptions with_stepper(IntegratorOptions o, int which) {
  switch (which) {
    case 1: o = {StepperKind::rkf78, 1e-12, 1e-12, 0.05}; break;  // the previous default
    case 2: o = {StepperKind::rkf78, 1e-10, 1e-10, 0.05}; break;
    default: break;                                                // the config's default
  }
  return o;
}

const char* stepper_label(int which) {
  return which == 0 ? "config default" : which == 1 ? "rkf78 1e-12" : "rkf78 1e-10";
}

}  // namespace

static void BM_Exp1Integrate(benchmark::State& st) {
  const BrightRunConfig c = exp1_config();
  const IntegratorOptions opt = with_stepper(c.integrator, int(st.range(0)));
  const BrightBreatherAnsatz ansatz(c.params, c.branch, c.theta, c.detuning, c.n0);
  const std::size_t beads = std::size_t(2 * c.N + 2);
  const long first = -c.N - 1;
  const DisplacementLattice chain(c.params, beads);
  const auto& L = chain.layout();
  State s0(L.size());
  for (std::size_t i = 0; i < beads; ++i) {
    const double n = double(first + long(i));
    ansatz.displacements(n, 0.0, L.primary(s0)[i], L.secondary(s0)[i]);
    ansatz.velocities(n, 0.0, L.primary_rate(s0)[i], L.secondary_rate(s0)[i]);
  }
  const double h = c.sample_every * ansatz.period();
  std::vector<double> times;
  for (long k = 0; k <= long(c.periods / c.sample_every + 1e-9); ++k) times.push_back(double(k) * h);
  IntegrationStats stats;
  double energy_drift = 0;
  for (auto _ : st) {
    State s = s0;
    stats = integrate_observed(chain, s, times, [](const State&, double) { return true; }, opt);
    benchmark::DoNotOptimize(s.data());
    st.PauseTiming();
    energy_drift = std::abs(chain.total_energy(s) / chain.total_energy(s0) - 1);
    st.ResumeTiming();
  }
  st.SetLabel(stepper_label(int(st.range(0))));
  st.counters["rhs_evals"] = double(stats.rhs_evaluations);
  st.counters["final_drift"] = energy_drift;
  st.counters["ns_per_site_eval"] = benchmark::Counter(
      double(stats.rhs_evaluations) * double(beads),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Exp1Integrate)->Arg(0)->Arg(2)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);

static void BM_Exp1Run(benchmark::State& st) {
  BrightRunConfig c = exp1_config();
  c.integrator = with_stepper(c.integrator, int(st.range(0)));
  BrightRunSummary s;
  for (auto _ : st) {
    s = run_resonant_chain_bright(c).summary;
    benchmark::DoNotOptimize(s.max_Ex);
  }
  st.SetLabel(stepper_label(int(st.range(0))));
  st.counters["rhs_evals"] = double(s.stats.rhs_evaluations);
  st.counters["drift"] = s.max_energy_drift;
  st.counters["max_E_x"] = s.max_Ex;
}
BENCHMARK(BM_Exp1Run)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->MinTime(2.0);

BENCHMARK_MAIN();
