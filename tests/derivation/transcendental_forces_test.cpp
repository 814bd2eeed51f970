// Lattice runs of force laws with elementary functions (docs/models.md, "Lattice runs"): the energy
// the lattice code generator integrates for every law of its table (sin, cos, tan, sinh, cosh, tanh,
// exp, log of a + b s, and (a + b s)^p) is the textbook potential of those forces, and the emitted
// accelerations are minus its gradient.
//
// The model, a Frenkel-Kontorova chain with a sinh bond and a tanh on-site term besides:
//   u_n'' = sinh(u_{n+1} - u_n) - sinh(u_n - u_{n-1}) - sin(u_n) - tanh(u_n)/2
// has (a textbook integral of each law) the energy
//   E = sum_n [ v_n^2/2 + (cosh(u_{n+1} - u_n) - 1) + (1 - cos u_n) + log(cosh u_n)/2 ].
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <vector>

#include "lrchain/errors.hpp"
#include "lrchain/model_compiler.hpp"
#include "scratch_cache.hpp"

namespace fs = std::filesystem;

namespace {

constexpr const char* kFrenkelKontorova = R"toml(name = "frenkel_kontorova"
description = "sine-Gordon chain with a sinh bond and a tanh on-site term"
[parameters]
g = { default = "1/2", description = "tanh on-site coefficient" }
[functions.B]
argument = "r"
expression = "sinh(r)"
[functions.S]
argument = "x"
expression = "sin(x)"
[functions.T]
argument = "x"
expression = "g*tanh(x)"
[[field]]
name = "u"
mass = "1"
force = "B(u[n+1] - u[n]) - B(u[n] - u[n-1]) - S(u[n]) - T(u[n])"
)toml";

// The textbook energy above, periodic ends.
double textbook_energy(const std::vector<double>& u, const std::vector<double>& v, double g) {
  const std::size_t n = u.size();
  double e = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = u[(i + 1) % n] - u[i];
    e += v[i] * v[i] / 2 + (std::cosh(r) - 1) + (1 - std::cos(u[i])) + g * std::log(std::cosh(u[i]));
  }
  return e;
}

// The lattice of a model file with one field of unit mass, periodic ends, at state (u, v): its emitted
// energy equals `expected` to round-off (relative `energy_tolerance`) and its accelerations are minus
// the central-difference gradient of that energy (O(h^2) = 1e-10 times third derivatives, `gradient_tolerance`).
void check_potential_and_forces(const fs::path& file, const double* parameters, const std::vector<double>& u,
                                const std::vector<double>& v, double expected, double energy_tolerance,
                                double gradient_tolerance) {
  const auto kernels = lrchain::compile_model_lattice(file);
  const bool has_energy = kernels->energy_density != nullptr;
  REQUIRE(has_energy);
  const long n = long(u.size());
  std::vector<double> e(n), a(n), work(std::size_t(kernels->workspace_size(n)));
  const auto energy = [&](const std::vector<double>& x) {
    kernels->energy_density(parameters, n, LRCHAIN_LATTICE_ENDS_PERIODIC, x.data(), v.data(), e.data(), work.data());
    double sum = 0;
    for (double y : e) sum += y;
    return sum;
  };
  REQUIRE(std::isfinite(energy(u)));
  CHECK(std::abs(energy(u) - expected) < energy_tolerance * std::abs(expected));
  kernels->displacement_accelerations(parameters, n, 1, u.data(), a.data(), work.data());
  const double h = 1e-5;
  for (long i = 0; i < n; ++i) {
    INFO("site " << i << " u = " << u[i]);
    std::vector<double> up = u, down = u;
    up[i] += h;
    down[i] -= h;
    CHECK(std::abs(a[i] + (energy(up) - energy(down)) / (2 * h)) < gradient_tolerance);
  }
}

// n random displacements and velocities in [-0.8, 0.8].
void random_state(unsigned seed, long n, std::vector<double>& u, std::vector<double>& v) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> amplitude(-0.8, 0.8);
  u.resize(std::size_t(n));
  v.resize(std::size_t(n));
  for (long i = 0; i < n; ++i) {
    u[i] = amplitude(random);
    v[i] = amplitude(random);
  }
}

}  // namespace

TEST_CASE("lattice code: sin, sinh and tanh force laws get their textbook potential, and the forces are its gradient" *
          doctest::test_suite("fast") * doctest::timeout(600)) {
  lrchain::test::ScratchCache scratch("lrchain-transcendental");
  const fs::path file = scratch.dir / "frenkel_kontorova.toml";
  std::ofstream(file) << kFrenkelKontorova;
  // The integrated potential equals the textbook one to round-off; the forces are its gradient.
  std::vector<double> u, v;
  random_state(7, 12, u, v);
  const double g = 0.5, parameters[] = {g};
  check_potential_and_forces(file, parameters, u, v, textbook_energy(u, v, g), 1e-13, 1e-8);
}

namespace {

// The rest of the table: an exp and cosh bond, and tan, log, cos and a power -1 on site,
//   u_n'' = F(u_{n+1} - u_n) - F(u_n - u_{n-1}) - W(u_n),
//   F(r) = exp(r) - cosh(r),  W(x) = tan(x)/4 + log(1 + x/2) + 1/(2 + x) - 1/2 + cos(x) - 1,
// with (textbook integrals from 0) the potentials
//   Phi_F(r) = exp(r) - sinh(r) - 1,
//   Phi_W(x) = -log|cos x|/4 + (2 + x) log(1 + x/2) - x + log(1 + x/2) - x/2 + sin(x) - x,
// defined for x > -2 and, for tan, on either side of its poles (one site is put beyond pi/2 below).
constexpr const char* kTableChain = R"toml(name = "antiderivative_table"
[functions.F]
argument = "r"
expression = "exp(r) - cosh(r)"
[functions.W]
argument = "x"
expression = "tan(x)/4 + log(1 + x/2) + 1/(2 + x) - 1/2 + cos(x) - 1"
[[field]]
name = "u"
mass = "1"
force = "F(u[n+1] - u[n]) - F(u[n] - u[n-1]) - W(u[n])"
)toml";

double table_energy(const std::vector<double>& u, const std::vector<double>& v) {
  const std::size_t n = u.size();
  double e = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double r = u[(i + 1) % n] - u[i], x = u[i];
    e += v[i] * v[i] / 2 + (std::exp(r) - std::sinh(r) - 1) - std::log(std::abs(std::cos(x))) / 4 +
         (2 + x) * std::log1p(x / 2) - x + std::log1p(x / 2) - x / 2 + std::sin(x) - x;
  }
  return e;
}

}  // namespace

TEST_CASE("lattice code: exp, cosh, tan (beyond pi/2 too), log, cos and 1/(a + b s) laws get their textbook potential" *
          doctest::test_suite("fast") * doctest::timeout(600)) {
  lrchain::test::ScratchCache scratch("lrchain-antiderivative-table");
  const fs::path file = scratch.dir / "antiderivative_table.toml";
  std::ofstream(file) << kTableChain;
  std::vector<double> u, v;
  random_state(11, 10, u, v);
  u[3] = 2.0;  // tan's next branch: cos(2) < 0, where -log(cos x) would be NaN
  check_potential_and_forces(file, nullptr, u, v, table_energy(u, v), 1e-12, 1e-7);
}

TEST_CASE("lattice code: a force law outside the integrated table, r exp(-r^2), is refused naming what lattice runs integrate" *
          doctest::test_suite("fast") * doctest::timeout(600)) {
  lrchain::test::ScratchCache scratch("lrchain-transcendental-refused");
  const fs::path file = scratch.dir / "gaussian_bond.toml";
  std::ofstream(file) << R"toml(name = "gaussian_bond"
[functions.F]
argument = "r"
expression = "r*exp(-r^2)"
[[field]]
name = "u"
mass = "1"
force = "F(u[n+1] - u[n]) - F(u[n] - u[n-1])"
)toml";
  CHECK_THROWS_WITH_AS(lrchain::compile_model_lattice(file),
                       doctest::Contains("exp, sin, cos, tan, sinh, cosh, tanh or log of a + b s"), lrchain::InputError);
}
