// The travelling wave job (jobs/wave_job.hpp) through the library: the Klein-Gordon chain without coupling
// (C = 0) is one anharmonic oscillator per site, whose frequency Landau & Lifshitz, Mechanics, Sec. 28 give:
// omega = w0 + (3b/(8 w0) - 5a^2/(12 w0^3)) A^2 + O(A^4) for x'' + w0^2 x + a x^2 + b x^3 = 0; the files
// the job writes; a refusal names its key; contact loss in the paper's chain is a failure, not a number.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <unistd.h>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/wave_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

namespace fs = std::filesystem;
using namespace lrchain;
using namespace lrchain::jobs::wave;

namespace {

WaveConfig config_of(const Model& model, const char* branch, double theta) {
  WaveConfig c;
  c.model = &model;
  c.kernels = &sim::lattice_kernels_of(model);
  c.branch = branch;
  c.theta = theta;
  return c;
}

}  // namespace

TEST_CASE("wave job: uncoupled Klein-Gordon sites oscillate at Landau and Lifshitz's anharmonic frequency" *
          doctest::test_suite("fast")) {
  const Model model = shipped_model("klein_gordon", {{"C", 0.0}});  // w0 = 1, a = 1/4, b = 1/2
  WaveConfig c = config_of(model, "branch0", 1.0);
  c.step = WaveStep::branch;
  c.amplitudes = {0.02, 0.04};
  const WaveResult r = run(c);
  REQUIRE(!r.failure);
  const double coefficient = 3 * 0.5 / 8 - 5 * 0.25 * 0.25 / 12;
  double previous_error = 0;
  for (const auto& w : r.waves) {
    const double expected = coefficient * w.amplitude * w.amplitude;
    const double error = std::abs((w.omega - 1) / expected - 1);
    MESSAGE("A " << w.amplitude << ": shift " << w.omega - 1 << ", Landau-Lifshitz " << expected << ", rel " << error);
    CHECK(error < 5e-3);
    if (previous_error > 0) CHECK(error > 3 * previous_error);  // O(A^2) relative error: doubling A quadruples it
    previous_error = error;
  }
}

TEST_CASE("wave job: stability writes its files, a bad key is named, contact loss is a failure" * doctest::test_suite("fast")) {
  const Model fput = shipped_model("fput");
  WaveConfig c = config_of(fput, "acoustic", 2.5);
  c.step = WaveStep::stability;
  c.amplitude = 0.02;
  c.k_points = 40;
  c.out = (fs::temp_directory_path() / ("lrchain-wave-job-" + std::to_string(::getpid()))).string();
  fs::remove_all(c.out);
  const WaveResult r = run(c);
  REQUIRE(r.stability);
  const nlohmann::json j = write(r, c.out);
  for (const char* file : {"profile.csv", "branch.csv", "growth.csv", "growth.gp", "summary.json"})
    CHECK(fs::exists(fs::path(c.out) / file));
  CHECK(j["stability"]["stable"] == false);
  CHECK(j["waves"].size() == 4);  // the ramp A/4 .. A
  fs::remove_all(c.out);

  WaveConfig bad = config_of(fput, "acoustic", 2.5);
  bad.amplitude = -1;
  try {
    validate(bad);
    FAIL("validate accepted amplitude -1");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "amplitude");
  }
  bad.amplitude = 0.1;
  bad.theta = 4;
  CHECK_THROWS_AS(validate(bad), InvalidParameter);

  // The paper's chain at theta = pi/2: the strain amplitude ~ sqrt(2) A exceeds delta0 = 4/9 at A = 0.4.
  const Model chain = shipped_model("resonant_chain");
  WaveConfig contact = config_of(chain, "optical", std::numbers::pi / 2);
  contact.step = WaveStep::branch;
  contact.amplitudes = {0.1, 0.2, 0.4};
  const WaveResult lost = run(contact);
  REQUIRE(lost.failure);
  CHECK(lost.failed_at == doctest::Approx(0.4));
  CHECK(lost.waves.size() == 2);
  CHECK(lost.failure->find("contact") != std::string::npos);
}
