// Throughput of coefficients(): the resonant chain's specialised path (scalar, through a loaded
// Model, and the batch loop) and the generic loaded-model path (target >= 10 million evaluations
// per second on one core).
#include <benchmark/benchmark.h>

#include <cstdint>
#include <numbers>
#include <vector>

#include "lrchain/coefficients.hpp"
#include "lrchain/coefficients_batch.hpp"
#include "lrchain/model.hpp"

// 1024 wavenumbers in (0, pi), cycled through by the scalar benchmarks.
static std::vector<double> wavenumbers() {
  std::vector<double> thetas(1024);
  for (std::size_t i = 0; i < thetas.size(); ++i) thetas[i] = std::numbers::pi * (i + 0.5) / thetas.size();
  return thetas;
}

static void BM_coefficients(benchmark::State& state) {
  const lrchain::Params p = lrchain::paper_params();
  const auto K = lrchain::taylor_coefficients(p);
  const auto branch = state.range(0) ? lrchain::Branch::optical : lrchain::Branch::acoustic;
  const std::vector<double> thetas = wavenumbers();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto c = lrchain::coefficients_unchecked(p, K, branch, thetas[i++ & 1023]);
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_coefficients)->Arg(1)->Arg(0);

// The validating entry point (parameter checks + K2,K3,K4 with one pow per call).
static void BM_coefficients_checked(benchmark::State& state) {
  const lrchain::Params p = lrchain::paper_params();
  double theta = 0.1;
  for (auto _ : state) {
    const auto c = lrchain::coefficients(p, lrchain::Branch::optical, theta);
    benchmark::DoNotOptimize(c);
    theta = theta < 3.0 ? theta + 1e-3 : 0.1;
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_coefficients_checked);

// The resonant chain as a loaded Model. Arg 1 (second): coefficients(), lib's dispatch to the
// specialised path; 0: the generic path, the chain's own emitted evaluators through function
// pointers and omega from det M's coefficients (coefficients_from_evaluators, what coefficients()
// of a Model was before the dispatch), as every other model is evaluated.
static void BM_coefficients_model(benchmark::State& state) {
  const lrchain::Model model = lrchain::shipped_model("resonant_chain");
  const lrchain::Index branch = model.branch(state.range(0) ? "optical" : "acoustic");
  const bool dispatch = state.range(1) != 0;
  const std::vector<double> thetas = wavenumbers();
  std::size_t i = 0;
  for (auto _ : state) {
    const double theta = thetas[i++ & 1023];
    const auto c = dispatch ? lrchain::coefficients(model, branch, theta)
                            : lrchain::coefficients_from_evaluators(model, branch, theta);
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_coefficients_model)->Args({1, 0})->Args({0, 0})->Args({1, 1})->Args({0, 1});

// Another model file's evaluators (0: resonant_chain, 1: diatomic_chain; optical branch). Arg 2 = 1:
// coefficients() (the full check of one wavenumber's numbers, as coeffs prints them); 0:
// coefficients_at() (the hot path of regime maps and scans: the screen for lost digits).
static void BM_coefficients_model_file(benchmark::State& state) {
  const lrchain::Model model = lrchain::shipped_model(state.range(0) ? "diatomic_chain" : "resonant_chain");
  const lrchain::Index branch = model.branch("optical");
  const bool full = state.range(1) != 0;
  const std::vector<double> thetas = wavenumbers();
  std::size_t i = 0;
  for (auto _ : state) {
    const double theta = thetas[i++ & 1023];
    lrchain::NlsCoefficients c;
    if (full) c = lrchain::coefficients_from_evaluators(model, branch, theta);
    else lrchain::coefficients_at(model.definition(), model.inputs().data(), branch, theta, c);
    benchmark::DoNotOptimize(c);
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_coefficients_model_file)->Args({0, 0})->Args({0, 1})->Args({1, 0})->Args({1, 1});

// The vectorised batch loop (lrchain/coefficients_batch.hpp) over 4096 wavenumbers per call.
static void BM_coefficients_batch(benchmark::State& state) {
  const lrchain::Params p = lrchain::paper_params();
  const auto branch = state.range(0) ? lrchain::Branch::optical : lrchain::Branch::acoustic;
  constexpr std::size_t n = 4096;
  std::vector<double> thetas(n), values[lrchain::kCoefficientColumnCount];
  std::vector<std::int8_t> regime(n);
  for (std::size_t i = 0; i < n; ++i) thetas[i] = std::numbers::pi * (i + 0.5) / n;
  lrchain::CoefficientColumns columns{};
  for (int k = 0; k < lrchain::kCoefficientColumnCount; ++k) columns.field[k] = (values[k] = std::vector<double>(n)).data();
  columns.regime = regime.data();
  for (auto _ : state) {
    lrchain::resonant_chain_coefficients_batch(p, branch, thetas, columns);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * n);
}
BENCHMARK(BM_coefficients_batch)->Arg(1)->Arg(0);

BENCHMARK_MAIN();
