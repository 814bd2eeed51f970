// Benchmark (issue 5): a bond-centred optical dark-breather branch (rho = 1/3, N = 101 sites per
// field) of 100 points with Floquet multipliers at every point.
#include <benchmark/benchmark.h>

#include "lrchain/ansatz/dark_breather.hpp"
#include "lrchain/sim/dark/continuation.hpp"

using namespace lrchain;
using namespace lrchain::sim::dark;

static void BM_DarkBranch100(benchmark::State& state) {
  const Params p;
  const int N = static_cast<int>(state.range(0));
  const double w0 = 2.445;
  for (auto _ : state) {
    const auto a = make_dark_breather_ansatz(p, Branch::optical, w0);
    ResonantChainShooting sh(p, N, DarkCenter::bond, ShootingMode::reversible);
    const auto res = newton_solve(sh, sh.unknowns_from_z(resonant_chain_dark_seed(a, DarkCenter::bond, N)), w0, {});
    ContinuationOptions o;
    o.max_points = 100;
    o.ds = 0.1;
    o.omega_max = 2.46;
    const auto br = continue_branch(sh, res.q, w0, o);
    state.counters["points"] = static_cast<double>(br.points.size());
    benchmark::DoNotOptimize(br.points.back().omega_b);
  }
}
BENCHMARK(BM_DarkBranch100)->Arg(101)->Unit(benchmark::kSecond)->Iterations(1);

static void BM_DarkFloquetPoint(benchmark::State& state) {
  const Params p;
  const int N = static_cast<int>(state.range(0));
  const double wb = 2.42;
  const auto a = make_dark_breather_ansatz(p, Branch::optical, wb);
  ResonantChainShooting sh(p, N, DarkCenter::bond, ShootingMode::reversible);
  const auto res = newton_solve(sh, sh.unknowns_from_z(resonant_chain_dark_seed(a, DarkCenter::bond, N)), wb, {});
  Eigen::VectorXd r;
  Eigen::MatrixXd J, A;
  for (auto _ : state) {
    sh.evaluate(res.q, wb, r, &J, &A);
    benchmark::DoNotOptimize(floquet_reversible(sh, A).max_modulus);
  }
}
BENCHMARK(BM_DarkFloquetPoint)->Arg(101)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
