// Lattice runs of force laws with elementary functions (docs/models.md, "Lattice runs"): the energy
// the lattice code generator integrates for sin, cosh, tanh, exp and log laws is the textbook
// potential of those forces, and the emitted accelerations are minus its gradient.
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

}  // namespace

TEST_CASE("lattice code: sin, sinh and tanh force laws get their textbook potential, and the forces are its gradient" *
          doctest::test_suite("fast") * doctest::timeout(600)) {
  lrchain::test::ScratchCache scratch("lrchain-transcendental");
  const fs::path file = scratch.dir / "frenkel_kontorova.toml";
  std::ofstream(file) << kFrenkelKontorova;
  const auto kernels = lrchain::compile_model_lattice(file);
  const bool has_energy = kernels->energy_density != nullptr;
  REQUIRE(has_energy);

  const long n = 12;
  const double g = 0.5;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> amplitude(-0.8, 0.8);
  std::vector<double> u(n), v(n), e(n), a(n), work(std::size_t(kernels->workspace_size(n)));
  for (long i = 0; i < n; ++i) {
    u[i] = amplitude(random);
    v[i] = amplitude(random);
  }
  const double parameters[] = {g};
  const auto energy = [&](const std::vector<double>& x) {
    kernels->energy_density(parameters, n, LRCHAIN_LATTICE_ENDS_PERIODIC, x.data(), v.data(), e.data(), work.data());
    double sum = 0;
    for (double y : e) sum += y;
    return sum;
  };
  // The integrated potential equals the textbook one to round-off.
  CHECK(std::abs(energy(u) - textbook_energy(u, v, g)) < 1e-13 * textbook_energy(u, v, g));

  // a_n = -dE/du_n (unit masses), by central differences of the emitted energy: O(h^2) = 1e-10.
  kernels->displacement_accelerations(parameters, n, 1, u.data(), a.data(), work.data());
  const double h = 1e-5;
  for (long i = 0; i < n; ++i) {
    std::vector<double> up = u, down = u;
    up[i] += h;
    down[i] -= h;
    const double gradient = (energy(up) - energy(down)) / (2 * h);
    CHECK(std::abs(a[i] + gradient) < 1e-8);
  }
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
