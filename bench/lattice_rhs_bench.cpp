// Cost of one lattice RHS evaluation (eq:Hertz, eq:Hertzd0S) per site, against the floor of one
// sqrt per bond (s*sqrt(s) for alpha = 3/2), for the 1001-site chain of experiment 1 (Sec. 4.2).
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "lrchain/params.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/strain_lattice.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {
State random_state(std::size_t sites) {
  std::mt19937 gen(3);
  std::uniform_real_distribution<double> d(-0.02, 0.02);
  State s(4 * sites);
  for (double& x : s) x = d(gen);
  return s;
}
}  // namespace

static void BM_DisplacementRHS(benchmark::State& st) {
  const std::size_t n = std::size_t(st.range(0));
  DisplacementLattice chain(Params{}, n);
  State s = random_state(n), ds(s.size());
  for (auto _ : st) {
    chain(s, ds, 0.0);
    benchmark::DoNotOptimize(ds.data());
    benchmark::ClobberMemory();
  }
  st.counters["ns_per_site"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate |
                                                                 benchmark::Counter::kInvert);
}
BENCHMARK(BM_DisplacementRHS)->Arg(1002)->Arg(4002);

static void BM_StrainRHS(benchmark::State& st) {
  const std::size_t n = std::size_t(st.range(0));
  StrainLattice chain(Params{}, n);
  State s = random_state(n), ds(s.size());
  for (auto _ : st) {
    chain(s, ds, 0.0);
    benchmark::DoNotOptimize(ds.data());
    benchmark::ClobberMemory();
  }
  st.counters["ns_per_site"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate |
                                                                 benchmark::Counter::kInvert);
}
BENCHMARK(BM_StrainRHS)->Arg(1001)->Arg(4001);

// The floor: s*sqrt(s) once per bond over contiguous arrays, nothing else.
static void BM_SqrtPerBondFloor(benchmark::State& st) {
  const std::size_t n = std::size_t(st.range(0));
  std::vector<double> r(n, 0.4), f(n);
  for (auto _ : st) {
    for (std::size_t i = 0; i < n; ++i) f[i] = r[i] * __builtin_sqrt(r[i]);
    benchmark::DoNotOptimize(f.data());
    benchmark::ClobberMemory();
  }
  st.counters["ns_per_site"] = benchmark::Counter(double(n), benchmark::Counter::kIsIterationInvariantRate |
                                                                 benchmark::Counter::kInvert);
}
BENCHMARK(BM_SqrtPerBondFloor)->Arg(1001)->Arg(4001);

BENCHMARK_MAIN();
