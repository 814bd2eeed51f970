// Benchmark of the regime maps (Sec. 3.3, Fig. 2): a 1000 x 1000 (theta, rho) map of sign(omega''
// h_tilde) for both branches, OpenMP-parallel. Target (issue 3): < 2 s wall time on 2 cores.
// Also the root-found focusing intervals of one parameter set.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <numbers>

#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/regime/regime_map.hpp"

using namespace lrchain;
using namespace lrchain::regime;

static void BM_ThetaRhoMapBothBranches(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const Params p{};  // paper parameters (alpha 3/2, delta0 4/9, kappa 1)
  const GridAxis rho{0.01, 30.0, n};
  const GridAxis theta{std::numbers::pi / n, std::numbers::pi, n};
  std::size_t focusing = 0;
  for (auto _ : state) {
    for (Branch b : {Branch::optical, Branch::acoustic}) {
      const RegimeMap m = theta_rho_map(p, b, rho, theta);
      focusing += m.values[m.values.size() / 2];
      benchmark::DoNotOptimize(m.values.data());
    }
  }
  state.counters["pixels"] = 2.0 * n * n;
  state.counters["threads"] = omp_get_max_threads();
  state.counters["ns_per_pixel_thread"] = benchmark::Counter(
      2.0 * n * n / omp_get_max_threads(),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  benchmark::DoNotOptimize(focusing);
}
BENCHMARK(BM_ThetaRhoMapBothBranches)->Arg(1000)->Unit(benchmark::kMillisecond)->UseRealTime();

static void BM_FocusingIntervals(benchmark::State& state) {
  const Params p{1.5, 4.0 / 9.0, 1.0, 10.0};
  for (auto _ : state) benchmark::DoNotOptimize(focusing_intervals(p, Branch::optical));
}
BENCHMARK(BM_FocusingIntervals)->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
