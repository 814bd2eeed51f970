// The stages of a wave's fate (sim/wave/wave_fate.hpp, StructureStage): the first and last time with
// localized structures held in most samples of a sliding window, on a series built by hand (its answer
// known by construction), and on real ring runs: the departure of a translation-invariant model's wave
// is measured on its strains, a model with an on-site potential's on its displacements.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "lrchain/jobs/wave_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "lrchain/sim/wave/wave_fate.hpp"

using namespace lrchain;
using namespace lrchain::sim::wave;

TEST_CASE("wave fate stages: a series built by hand" * doctest::test_suite("fast")) {
  // 1000 samples at t = 10 k. Structures at k in [200, 500) except every third sample (2/3 of them), two
  // of them at k in [300, 400); a burst of 10 samples at k in [800, 810) that no 100-sample window holds
  // in most of its samples. By construction: the first held window's first structure is at k = 200
  // (200 = 3 66 + 2 holds one), the last one's last at k = 499 (3 166 + 1); the window [300, 400) holds 66
  // twos and 34 zeros: median 2.
  std::vector<double> t, count;
  for (int k = 0; k < 1000; ++k) {
    t.push_back(10.0 * k);
    double c = 0;
    if (k >= 200 && k < 500 && k % 3 != 0) c = (k >= 300 && k < 400) ? 2 : 1;
    if (k >= 800 && k < 810) c = 1;
    count.push_back(c);
  }
  const StructureStage stage = structure_stage(t, count, 100);
  REQUIRE(stage.found());
  CHECK(stage.from == 2000.0);
  CHECK(stage.until == 4990.0);
  CHECK(stage.count == 2);
  CHECK(std::isnan(stage.width));  // widths are the caller's (wave_fate: the dark structures')
  // With a 10-sample window the burst is a stage of its own: the stage runs on to its last sample, 809.
  const StructureStage fine = structure_stage(t, count, 10);
  CHECK(fine.from == 2000.0);
  CHECK(fine.until == 8090.0);
  // A window longer than the series is the whole series: 200 of 1000 samples hold one, not most.
  CHECK_FALSE(structure_stage(t, count, 5000).found());
  const StructureStage none = structure_stage(t, std::vector<double>(1000, 0.0), 100);
  CHECK_FALSE(none.found());
  CHECK(std::isnan(none.from));
  CHECK(none.count == 0);
}

namespace {

jobs::wave::WaveConfig fate_of(const Model& model, double theta, double amplitude, Index sites, double periods) {
  jobs::wave::WaveConfig c;
  c.step = jobs::wave::WaveStep::fate;
  c.model = &model;
  c.kernels = &sim::lattice_kernels_of(model);
  c.theta = theta;
  c.amplitude = amplitude;
  c.k_points = 40;
  c.ring_sites = sites;
  c.periods = periods;
  return c;
}

}  // namespace

TEST_CASE("wave fate stages: fput's zone-boundary wave passes into bright breathers" * doctest::test_suite("fast")) {
  // Pure FPU-beta (a = 0) at theta = 3.1 (2 pi 63/128 on 128 sites), A = 0.5: the zone-boundary wave's
  // modulational instability breaks it into chaotic breathers that gather its energy in a few sites
  // (Cretegny, Dauxois, Ruffo & Torcini, Physica D 121, 109 (1998)). Measured (lrchain wave fate --model
  // models/fput.toml --set a=0 --theta 3.1 --amplitude 0.5 --ring-sites 128 --periods 400): broke at t =
  // 32.1, P < 1/4 in most samples from t = 441.5 to the end (1070.3), 4 peaks; no dark structure.
  // The wave solved by the job (step solve at the ring's theta), its ring run by wave_fate itself (the
  // job's fate step adds the growth rates at the ring's 64 K, not needed here).
  const Model fput = shipped_model("fput", {{"a", 0.0}});
  jobs::wave::WaveConfig c = fate_of(fput, jobs::wave::ring_theta(3.1, 128), 0.5, 128, 400);
  c.step = jobs::wave::WaveStep::solve;
  const jobs::wave::WaveResult solved = jobs::wave::run(c);
  REQUIRE_FALSE(solved.failure);
  WaveFateOptions o;
  o.ring_sites = 128;
  o.periods = 400;
  const WaveFateResult f = wave_fate(*c.kernels, sim::lattice_parameters(fput), solved.waves.back(), o);
  CHECK(f.strain_deviation);  // fput's energy depends on differences only
  CHECK(f.broke_at == doctest::Approx(32.1).epsilon(0.05));
  CHECK(f.fate == WaveFate::localized);
  CHECK(f.kind == LocalizedKind::bright);
  REQUIRE(f.bright_stage.found());
  CHECK(f.bright_stage.from == doctest::Approx(441.5).epsilon(0.1));
  CHECK(f.bright_stage.until == f.t.back());  // P < 1/4 at the end: the stage lasts to it
  CHECK(f.bright_stage.count >= 1);
  // Inside the stage most samples are localized: P < 1/4 (recounted from the series).
  Index inside = 0, localized = 0;
  for (std::size_t i = 0; i < f.t.size(); ++i)
    if (f.t[i] >= f.bright_stage.from && f.t[i] <= f.bright_stage.until)
      ++inside, localized += f.participation[i] < kLocalizedParticipation;
  CHECK(2 * localized > inside);
  CHECK_FALSE(f.dark_stage.found());
  CHECK(std::isnan(f.dark_stage.width));
}

TEST_CASE("wave fate: a model with an on-site potential measures the departure on its displacements" *
          doctest::test_suite("fast")) {
  // klein_gordon's on-site term makes a uniform displacement cost energy: its deviation stays that of the
  // displacements, and its exact wave with no noise starts at the wave itself (round-off). fput's strain
  // deviation of the same seed is round-off too, and its modulated seed c_n = 1 + b cos(2 pi n / N) departs
  // at t = 0 by max_n |b (c_{n+1} U_{n+1} - c_n U_n)| / (2 A sin(theta / 2)) = 0.0095083 for b = 0.01 (computed
  // from the solved profile, `lrchain wave solve --model fput --theta 10*pi/64 --amplitude 0.03`, interpolated
  // by its Fourier series; a plane wave would give 0.00928, the harmonics add the rest).
  const Model kg = shipped_model("klein_gordon");
  jobs::wave::WaveConfig c = fate_of(kg, 1.0, 0.05, 64, 2);
  c.noise = 0;
  const jobs::wave::WaveResult r = jobs::wave::run(c);
  REQUIRE(r.fate);
  CHECK_FALSE(r.fate->strain_deviation);
  CHECK(r.fate->deviation.front() < 1e-12);
  const auto j = jobs::wave::to_json(r)["fate"];
  CHECK(j["deviation_of"] == "displacement");
  for (const char* key : {"dark_from", "dark_until", "dark_stage_count", "dark_stage_width", "bright_from"})
    CHECK(j[key].is_null());  // two periods of an intact wave: no stage
  const Model fput = shipped_model("fput");
  jobs::wave::WaveConfig m = fate_of(fput, 0.5, 0.03, 64, 1);
  m.noise = 0;
  const jobs::wave::WaveResult exact = jobs::wave::run(m);
  REQUIRE(exact.fate);
  CHECK(exact.fate->strain_deviation);
  CHECK(exact.fate->deviation.front() < 1e-12);
  m.modulation = 0.01;
  const jobs::wave::WaveResult modulated = jobs::wave::run(m);
  REQUIRE(modulated.fate);
  CHECK(modulated.fate->deviation.front() == doctest::Approx(0.0095083).epsilon(1e-5).scale(0));
}
