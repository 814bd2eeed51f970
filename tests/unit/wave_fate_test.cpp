// What a travelling wave becomes (jobs/wave_job.hpp, step fate; sim/wave/wave_fate.hpp): a wave the
// Floquet-Bloch spectrum calls stable stays the wave on the ring; an unstable one breaks up when its
// noise, grown at the computed largest rate, reaches a tenth of A: at t ~ ln(0.1 / noise) / rate (a
// second method for the rate, as wave_ring_growth_test.cpp), within the slack of the noise's projection
// onto the growing mode; the spectral entropy of one plane wave is log 2 / log N (its modes +-j).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/wave_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

using namespace lrchain;
using namespace lrchain::jobs::wave;

namespace {

WaveConfig fate_of(const Model& model, double theta, double amplitude) {
  WaveConfig c;
  c.step = WaveStep::fate;
  c.model = &model;
  c.kernels = &sim::lattice_kernels_of(model);
  c.theta = theta;
  c.amplitude = amplitude;
  c.k_points = 40;
  c.ring_sites = 64;
  c.periods = 400;
  return c;
}

}  // namespace

TEST_CASE("wave fate: a calm wave stays, an unstable one breaks up when the ring's growth says" *
          doctest::test_suite("fast")) {
  const Model fput = shipped_model("fput");
  // theta = 0.5 (2 pi 5/64 on the ring): the NLS is defocusing, and the 40-point K grid finds no
  // growth at A = 0.03. The ring's own K = 2 pi m / 64 find the narrow band that the grid misses: a
  // 2000-point scan (lrchain wave stability --k-points 2000) puts it on [1.0788, 1.0843] with its peak
  // 5.05e-5 at K = 1.0819, and the ring holds K = 2 pi 11/64 = 1.0799 inside it. Over 400 periods that
  // grows e^0.2, so the wave stays intact, not "stable".
  const WaveResult calm = run(fate_of(fput, 0.5, 0.03));
  REQUIRE(calm.fate);
  CHECK(calm.stability->stable);
  CHECK(calm.ring_growth.at_k == doctest::Approx(2 * std::numbers::pi * 11 / 64).epsilon(1e-12));
  CHECK(calm.ring_growth.rate > 3e-5);
  CHECK(calm.ring_growth.rate < 5.06e-5);
  CHECK(calm.fate->fate == sim::wave::WaveFate::intact);
  CHECK(calm.fate->broke_at < 0);
  CHECK(calm.fate->max_relative_energy_drift < 1e-10);  // srkn11b, symplectic
  CHECK(calm.fate->entropy.front() == doctest::Approx(std::log(2.0) / std::log(64.0)).epsilon(0.02));
  CHECK(calm.theta == doctest::Approx(2 * std::numbers::pi * 5 / 64));  // the ring's nearest 2 pi j / N
  // An intact plane wave holds no dark structure at any sample; its envelope window is the odd number
  // nearest its wavelength 64/5 = 12.8 sites. fput's band is omega = 2 sin(theta / 2) on [0, 2].
  CHECK(calm.fate->envelope_window == 13);
  CHECK(*std::max_element(calm.fate->dark.begin(), calm.fate->dark.end()) == 0);
  CHECK(calm.fate->kind == sim::wave::LocalizedKind::none);
  CHECK(calm.band[0] == doctest::Approx(0).scale(1));
  CHECK(calm.band[1] == doctest::Approx(2).epsilon(1e-12));
  // The JSON's theta is the wave's (the ring's), the request beside it; fate records the stability options.
  const auto j = to_json(calm);
  CHECK(j["theta"].get<double>() == calm.theta);
  CHECK(j["requested_theta"].get<double>() == 0.5);
  CHECK(j["options"]["k_points"].get<Index>() == 40);

  // theta = 2.5, A = 0.3: modulationally unstable (measured 96.8 vs a predicted 80.5 on 128 sites)
  const WaveResult broken = run(fate_of(fput, 2.5, 0.3));
  REQUIRE(broken.fate);
  REQUIRE(!broken.stability->stable);
  // The prediction takes the largest rate among the K = 2 pi m / 64 the ring holds, at most the
  // continuous spectrum's largest.
  REQUIRE(broken.ring_growth.rate > 0);
  CHECK(broken.ring_growth.rate <= broken.stability->largest_rate * (1 + 1e-12));
  CHECK(std::remainder(broken.ring_growth.at_k * 64 / (2 * std::numbers::pi), 1.0) == doctest::Approx(0).scale(1));
  const double predicted = std::log(sim::wave::kBrokenDeviation / 1e-4) / broken.ring_growth.rate;
  CHECK(broken.fate->broke_at > 0.8 * predicted);
  CHECK(broken.fate->broke_at < 1.5 * predicted);
  CHECK(broken.fate->fate != sim::wave::WaveFate::stable);
  CHECK(broken.fate->fate != sim::wave::WaveFate::intact);
  CHECK(broken.fate->t.size() == 401);

  // Too few steps per period: the energy drifts (2.4e-4 measured at 8 steps vs 1.4e-10 at 40, for
  // A = 1.5 on 32 sites); the fate is refused as the ring run's failure, not classified.
  WaveConfig coarse = fate_of(fput, 2.5, 1.5);
  coarse.ring_sites = 32;
  coarse.periods = 50;
  coarse.steps_per_period = 8;
  const WaveResult drifted = run(coarse);
  CHECK(drifted.ring_run_failed);
  REQUIRE(drifted.failure);
  CHECK(drifted.failure->find("energy drift") != std::string::npos);
  CHECK_FALSE(drifted.fate);

  // --noise 0 --modulation b: the ring starts from the exact wave times 1 + b cos(2 pi n / N) (the paper's
  // eq:cimi seed), so its first deviation (fput: of the strains) is about b: 0.0095083 for b = 0.01
  // (tests/unit/wave_fate_stage_test.cpp); without either it is the wave itself, to round-off. No noise: no
  // predicted breakup.
  WaveConfig seeded = fate_of(fput, 0.5, 0.03);
  seeded.periods = 1;
  seeded.noise = 0;
  const WaveResult exact = run(seeded);
  REQUIRE(exact.fate);
  CHECK(exact.fate->deviation.front() < 1e-12);
  CHECK(to_json(exact)["fate"]["predicted_breakup"].is_null());
  seeded.modulation = 0.01;
  const WaveResult modulated = run(seeded);
  REQUIRE(modulated.fate);
  CHECK(modulated.fate->deviation.front() == doctest::Approx(0.0095083).epsilon(1e-5).scale(0));
  CHECK(to_json(modulated)["fate"]["modulation"].get<double>() == 0.01);

  // refusals name their key
  WaveConfig bad = fate_of(fput, 2.5, 0.3);
  bad.ring_sites = 4;
  try {
    validate(bad);
    FAIL("ring_sites = 4 was accepted");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "ring_sites");
  }
  bad = fate_of(fput, 2.5, 0.3);
  bad.modulation = 1;  // 1 + cos(2 pi n / N) vanishes at n = N/2: refused, [0, 1)
  try {
    validate(bad);
    FAIL("modulation = 1 was accepted");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "modulation");
  }
  bad = fate_of(fput, 0.01, 0.3);  // moves to theta = 0 on 64 sites
  CHECK_THROWS_AS(validate(bad), InvalidParameter);
}
