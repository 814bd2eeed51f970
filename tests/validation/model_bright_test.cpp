// Bright breathers of model files (sim/model_bright_run.hpp) against the NLS ansatz built from
// the derived coefficients: over 200 T_b the lattice stays within 5 % of the ansatz (max E_x), and
// since the ansatz's relative error is O(epsilon) with epsilon^2 ~ |omega_b - omega|, quartering
// the detuning must divide max E_x by about 2 (we require >= 1.5).
#include <doctest/doctest.h>

#include <cstdio>
#include <numbers>

#include "lrchain/sim/model_bright_run.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {

struct BrightCase {
  std::string model, branch;
  double theta, detuning;  // detuning: the larger of the two runs (the second is a quarter of it)
  long N;
  double n0;
};

void check_model_bright(const BrightCase& k) {
  const Model model = shipped_model(k.model);
  ModelBrightConfig c;
  c.branch = model.branch(k.branch);
  c.theta = k.theta;
  c.N = k.N;
  c.n0 = k.n0;
  double max_error[2];
  for (int quartered = 0; quartered < 2; ++quartered) {
    c.detuning = k.detuning / (quartered ? 4 : 1);
    const ModelBrightResult r = run_model_bright(model, lattice_kernels_of(model), c);
    max_error[quartered] = r.max_error[0];
    std::printf("bright %s %s theta %.4f detuning %.3g: max E_x %.4f (fields:", k.model.c_str(), k.branch.c_str(),
                k.theta, *c.detuning, r.max_error[0]);
    for (double e : r.max_error) std::printf(" %.4f", e);
    std::printf("), energy drift %.2e, centre speed %.6f vs c %.6f\n", r.max_energy_drift,
                r.centre_speed.value_or(0.0), r.group_velocity);
  }
  std::printf("bright %s: max E_x ratio (detuning / 4) %.2f\n", k.model.c_str(), max_error[0] / max_error[1]);
  CHECK(max_error[0] < 0.05);
  CHECK(max_error[1] < 0.05);
  CHECK(max_error[0] / max_error[1] >= 1.5);
}

}  // namespace

TEST_CASE("model bright: klein_gordon at theta = 3 pi/4 stays within 5 % of the NLS ansatz over 200 T_b") {
  check_model_bright({"klein_gordon", "branch0", 3 * std::numbers::pi / 4, 1e-4, 500, 0});
}

TEST_CASE("model bright: fput stays within 5 % of the NLS ansatz over 200 T_b") {
  check_model_bright({"fput", "acoustic", std::numbers::pi / 2, -1e-4, 1000, -600});
}
