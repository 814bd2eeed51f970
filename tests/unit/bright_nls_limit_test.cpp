// The NLS limit of exact bright breathers on a second model (the first, klein_gordon, is in
// bright_breather_job_test.cpp): the FPU chain's bond-centred (Page) breather above the top of its band,
// omega(pi) = 2 (fput defaults: K2 = 1, a = 1/4, b = 1/2: omega'' = -1/2, h_tilde = 5, focusing).
// The seed carries the second-order terms, so it misses the exact profile by O(epsilon^2) = O(detuning):
// the relative difference D falls linearly with the detuning (measured D / detuning = 0.403, 0.379, 0.369
// at 0.04, 0.02, 0.01), and the peak and width approach the NLS's.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::bright_breather;

TEST_CASE("bright job: the fput Page breather tends to the NLS seed linearly in the detuning" * doctest::test_suite("fast")) {
  const Model fput = shipped_model("fput");
  std::vector<double> D, peak, width;
  for (const double detuning : {0.04, 0.02, 0.01}) {
    CAPTURE(detuning);
    BrightBreatherConfig c;
    c.step = BrightStep::solve;
    c.model = &fput;
    c.kernels = sim::shipped_lattice_kernels("fput");
    c.omega_b = 2 + detuning;
    c.sites = 121;
    c.center = "bond";
    validate(c);
    const BrightBreatherResult r = run(c);
    INFO(failure(r).value_or(""));
    REQUIRE(!failure(r));
    CHECK(r.edge.nls.omega == doctest::Approx(2.0).epsilon(1e-12));
    CHECK(r.edge.theta == doctest::Approx(std::numbers::pi));
    CHECK(r.profile.localized);
    D.push_back(r.seed_difference);
    peak.push_back(std::abs(r.profile.peak - r.seed_profile.peak) / r.profile.peak);
    width.push_back(std::abs(r.profile.width - r.seed_profile.width) / r.profile.width);
    CHECK(r.seed_difference / detuning == doctest::Approx(0.38).epsilon(0.1));
  }
  for (std::size_t k = 0; k + 1 < D.size(); ++k) {
    CHECK(D[k] / D[k + 1] >= 1.7);  // halving the detuning halves D
    CHECK(D[k] / D[k + 1] <= 2.4);
    CHECK(peak[k + 1] < peak[k]);
    CHECK(width[k + 1] < width[k]);
  }
  CHECK(peak.back() < 5e-3);
  CHECK(width.back() < 1e-2);
}
