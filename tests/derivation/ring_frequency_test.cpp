// The derived NLS coefficient h against direct lattice integration: a plane wave of amplitude U on
// a periodic ring of the generated model lattice (theta = 2 pi k / N) oscillates at
// omega + h U^2 / 4 + O(U^4) (NLS i A_tau = h |A|^2 A for a uniform envelope, u_0 = eps (A E + c.c.),
// so U = 2 eps |A|; no mean flow on a ring). The measured shift is compared with the prediction at
// two amplitudes: the relative disagreement is O(U^2), so halving U must divide it by about 4.
#include <doctest/doctest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>

#include "lrchain/derivation/branches.hpp"
#include "lrchain/derivation/model_derivation.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "lrchain/sim/ring_run.hpp"

using namespace lrchain::derivation;
using namespace lrchain::sim;

namespace {

struct RingPrediction {
  double omega = 0, h = 0;
  std::vector<std::complex<double>> kernel;  // Bloch vector, first entry 1
  std::vector<double> parameters;
};

RingPrediction predict(const std::string& model, double theta, std::size_t branch) {
  const Symbols s;
  ModelFile file = load_model_file(std::string(LRCHAIN_SOURCE_DIR) + "/models/" + model + ".toml");
  const GiNaC::exmap values = parameter_values(file, {});
  RingPrediction p;
  for (const auto& parameter : file.parameters) p.parameters.push_back(parameter.default_value.to_double());
  auto derived = derive_model(std::move(file), values, s);
  const BranchPoint point(derived->coefficients, s, derived->values, theta, branch);
  p.omega = point.value(s.omega).to_double();
  p.h = point.value(derived->coefficients.h).to_double();
  for (const auto& k : derived->coefficients.kernel)
    p.kernel.emplace_back(point.value(k).to_double(), point.value(-GiNaC::I * k).to_double());
  return p;
}

void check_ring(const std::string& model, std::size_t branch, double amplitude) {
  const std::size_t sites = 16, mode_number = 4;  // theta = pi/2
  const double theta = 2 * std::numbers::pi * double(mode_number) / double(sites);
  const RingPrediction p = predict(model, theta, branch);
  const lrchain_lattice_kernels* kernels = shipped_lattice_kernels(model);
  REQUIRE(kernels != nullptr);
  // The derivation's kernel and omega (not the lattice code's Bloch mode) set up the plane wave.
  BlochMode mode;
  mode.omega = p.omega;
  mode.kernel = p.kernel;
  const std::vector<BlochMode> lattice_modes = bloch_modes(*kernels, p.parameters, theta);
  REQUIRE(branch < lattice_modes.size());
  CHECK(lattice_modes[branch].omega == doctest::Approx(p.omega).epsilon(1e-12));
  for (std::size_t f = 0; f < p.kernel.size(); ++f)
    CHECK(std::abs(lattice_modes[branch].kernel[f] - p.kernel[f]) < 1e-10 * (1 + std::abs(p.kernel[f])));
  double error[2];
  for (int halving = 0; halving < 2; ++halving) {
    const double U = amplitude / (1 << halving);
    const double shift = measure_ring_frequency(*kernels, p.parameters, mode, long(sites), long(mode_number), U, 400, 80) - p.omega;
    const double predicted = p.h * U * U / 4;
    error[halving] = std::abs(shift - predicted) / std::abs(predicted);
    std::printf("ring %s branch %zu theta pi/2: omega %.10f h %.6g U %.4g shift measured %.6e predicted %.6e (rel. diff %.2e)\n",
                model.c_str(), branch, p.omega, p.h, U, shift, predicted, error[halving]);
  }
  CHECK(error[0] < 0.05);
  CHECK(error[1] < 0.01);
  CHECK(error[1] < error[0] / 3);
}

}  // namespace

TEST_CASE("ring: plane-wave frequency shift on the fput lattice equals h U^2/4" * doctest::test_suite("fast")) {
  check_ring("fput", 0, 0.04);
}

TEST_CASE("ring: plane-wave frequency shift on the klein_gordon lattice equals h U^2/4" * doctest::test_suite("fast")) {
  check_ring("klein_gordon", 0, 0.04);
}

TEST_CASE("ring: plane-wave frequency shift on the resonant chain (acoustic, optical) equals h U^2/4" * doctest::test_suite("fast")) {
  check_ring("resonant_chain", 0, 0.02);
  check_ring("resonant_chain", 1, 0.02);
}
