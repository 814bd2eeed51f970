// Cost of one lattice RHS evaluation (eq:Hertz, eq:Hertzd0S) per site, against the floor of one
// sqrt per bond (s*sqrt(s) for alpha = 3/2), for the 1001-site chain of experiment 1 (Sec. 4.2).
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <string>
#include <random>
#include <vector>

#include "lrchain/params.hpp"
#include "lrchain/sim/contact_law.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/model_lattice.hpp"
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
// Reports the time per site (per evaluation) as the counter ns_per_site.
void per_site_counter(benchmark::State& st, std::size_t sites) {
  st.counters["ns_per_site"] = benchmark::Counter(
      double(sites), benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
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
  per_site_counter(st, n);
}
BENCHMARK(BM_DisplacementRHS)->Arg(1002)->Arg(4002);

// Accelerations only (what the symplectic RKN steppers call): q = [u v] -> [u'' v''].
static void BM_DisplacementAcceleration(benchmark::State& st) {
  const std::size_t n = std::size_t(st.range(0));
  DisplacementLattice chain(Params{}, n);
  State s = random_state(n), a(2 * n);
  for (auto _ : st) {
    chain.acceleration(s.data(), a.data(), 0.0);
    benchmark::DoNotOptimize(a.data());
    benchmark::ClobberMemory();
  }
  per_site_counter(st, n);
}
BENCHMARK(BM_DisplacementAcceleration)->Arg(1002)->Arg(4002);

// Bond forces alone (the vectorised s*sqrt(s) loop of contact_law.cpp).
static void BM_BondForces(benchmark::State& st) {
  const std::size_t n = std::size_t(st.range(0));
  const ContactLaw law = make_contact_law(Params{});
  State u = random_state(n);
  std::vector<double> f(n);
  for (auto _ : st) {
    bond_forces_from_displacements(law, std::span(u).first(n), std::span(f).first(n - 1));
    benchmark::DoNotOptimize(f.data());
    benchmark::ClobberMemory();
  }
  per_site_counter(st, n);
}
BENCHMARK(BM_BondForces)->Arg(1002)->Arg(4002);

static void BM_StrainRHS(benchmark::State& st) {
  const std::size_t n = std::size_t(st.range(0));
  StrainLattice chain(Params{}, n);
  State s = random_state(n), ds(s.size());
  for (auto _ : st) {
    chain(s, ds, 0.0);
    benchmark::DoNotOptimize(ds.data());
    benchmark::ClobberMemory();
  }
  per_site_counter(st, n);
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
  per_site_counter(st, n);
}
BENCHMARK(BM_SqrtPerBondFloor)->Arg(1001)->Arg(4001);

// The floor with packed sqrt: the same loop built for this CPU's widest vectors (target_clones,
// errno-free sqrt), i.e. the best one sqrt per bond can do without -march flags.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
__attribute__((target_clones("avx512f", "avx2", "default"), optimize("fast-math"), noinline))
#endif
static void packed_sqrt_floor(const double* __restrict r, double* __restrict f, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    double s = r[i];
    s = s > 0.0 ? s : 0.0;
    f[i] = s * __builtin_sqrt(s);
  }
}
static void BM_PackedSqrtPerBondFloor(benchmark::State& st) {
  const std::size_t n = std::size_t(st.range(0));
  std::vector<double> r(n, 0.4), f(n);
  for (auto _ : st) {
    packed_sqrt_floor(r.data(), f.data(), n);
    benchmark::DoNotOptimize(f.data());
    benchmark::ClobberMemory();
  }
  per_site_counter(st, n);
}
BENCHMARK(BM_PackedSqrtPerBondFloor)->Arg(1001)->Arg(4001);

// Times the generated lattice's accelerations at state `s`, reported per site of `n`.
static void time_generated_rhs(benchmark::State& st, const CompiledLattice& lattice, const State& s, std::size_t n) {
  State ds(s.size());
  for (auto _ : st) {
    lattice(s, ds, 0.0);
    benchmark::DoNotOptimize(ds.data());
    benchmark::ClobberMemory();
  }
  per_site_counter(st, n);
}

// The defaults of models/<name>.toml by parameter name.
const std::map<std::string, double> kDefaultParameters{{"alpha", 1.5}, {"delta0", 4.0 / 9.0}, {"kappa", 1}, {"rho", 1.0 / 3.0},
                                                       {"a", 0.25}, {"b", 0.5}, {"C", 0.1}, {"w0", 1}, {"m", 2},
                                                       {"k1", 1}, {"b1", -0.25}, {"g1", 0.125}, {"k2", 1}, {"b2", 0}, {"g2", 0.1}};

// The generated lattices of the shipped models (models/*.toml at their defaults) in both forms:
// strain form (translation-invariant models only; an on-site model is skipped there) and
// displacement form; periodic ends. The first argument indexes shipped_lattice_models(), the second
// is the number of sites, the third the form (0 displacement, 1 strain).
static void BM_ModelRHS(benchmark::State& st) {
  const std::string name = shipped_lattice_models().at(std::size_t(st.range(0)));
  const std::size_t n = std::size_t(st.range(1));
  const LatticeForm form = st.range(2) == 1 ? LatticeForm::strain : LatticeForm::displacement;
  const lrchain_lattice_kernels& k = *shipped_lattice_kernels(name);
  if (form == LatticeForm::strain && !k.strain_accelerations) {
    st.SkipWithError((name + ": on-site model, no strain form").c_str());
    return;
  }
  std::vector<double> parameters;
  for (int i = 0; i < k.parameter_count; ++i) parameters.push_back(kDefaultParameters.at(k.parameter_names[i]));
  CompiledLattice lattice(k, parameters, n, true, form);
  State s = random_state(n);
  s.resize(2 * lattice.positions());
  st.SetLabel(name + (form == LatticeForm::strain ? " (strain)" : " (displacement)"));
  time_generated_rhs(st, lattice, s, n);
}
BENCHMARK(BM_ModelRHS)->ArgsProduct({{0, 1, 2, 3, 4, 5, 6}, {1001, 4001}, {0, 1}});

// Every translation-invariant shipped model in strain form with free ends (the bond instances
// touching beads beyond the chain dropped), to compare with its ring above.
static void BM_ModelFreeEndsStrainRHS(benchmark::State& st) {
  const std::string name = shipped_lattice_models().at(std::size_t(st.range(0)));
  const std::size_t n = std::size_t(st.range(1));
  const lrchain_lattice_kernels& k = *shipped_lattice_kernels(name);
  if (!k.strain_accelerations) {
    st.SkipWithError((name + ": on-site model, no strain form").c_str());
    return;
  }
  std::vector<double> parameters;
  for (int i = 0; i < k.parameter_count; ++i) parameters.push_back(kDefaultParameters.at(k.parameter_names[i]));
  CompiledLattice lattice(k, parameters, n, false, LatticeForm::strain);
  State s = random_state(n);
  s.resize(2 * lattice.positions());
  st.SetLabel(name + " (strain, free ends)");
  time_generated_rhs(st, lattice, s, n);
}
BENCHMARK(BM_ModelFreeEndsStrainRHS)->ArgsProduct({{0, 1, 2, 3, 4, 5, 6}, {1001, 4001}});

// The resonant chain through the generated kernels with the specialised lattice's zero-strain ends
// (compare with BM_StrainRHS).
static void BM_GeneratedResonantStrainRHS(benchmark::State& st) {
  const std::size_t n = std::size_t(st.range(0));
  const Params p;
  CompiledLattice lattice(*shipped_lattice_kernels("resonant_chain"), {p.alpha, p.delta0, p.kappa, p.rho}, n, false,
                       LatticeForm::strain);
  time_generated_rhs(st, lattice, random_state(n), n);
}
BENCHMARK(BM_GeneratedResonantStrainRHS)->Arg(1001)->Arg(4001);

// The same in displacement form with fixed ends (compare with BM_DisplacementRHS, whose state is
// also [u v u' v'] per site).
static void BM_GeneratedResonantDisplacementRHS(benchmark::State& st) {
  const std::size_t n = std::size_t(st.range(0));
  const Params p;
  CompiledLattice lattice(*shipped_lattice_kernels("resonant_chain"), {p.alpha, p.delta0, p.kappa, p.rho}, n, false,
                       LatticeForm::displacement);
  time_generated_rhs(st, lattice, random_state(n), n);
}
BENCHMARK(BM_GeneratedResonantDisplacementRHS)->Arg(1002)->Arg(4002);

BENCHMARK_MAIN();
