// Experiment 7's dark stage in a lattice that is not the paper's chain: resonant_chain_polynomial with
// the cubic Taylor polynomial of the paper's Hertz law at delta0 = 0.27 (k1 = alpha delta0^(alpha-1),
// b1 = -alpha(alpha-1)/2 delta0^(alpha-2), g1 = alpha(alpha-1)(alpha-2)/6 delta0^(alpha-3), alpha = 3/2),
// a linear resonator (k2 = 1, g2 = 0) and rho = 0.32, seeded as experiment 7 (theta0 = 252 pi / 401,
// A = 0.03, modulation 0.01, no noise, 8500 carrier periods on 401 sites). The expected stage is the
// paper's chain's (tests/validation/wave_fate_exp7_test.cpp: 28890 to 38232, 35.1 sites wide, 0.79 deep),
// since the weakly nonlinear dynamics (the NLS) sees only the cubic polynomial. Measured here: 29254 to
// 38905, 2 structures, 35.4 sites wide, 0.78 deep; broke at 9849 (the paper's chain: 9619).
#include <doctest/doctest.h>

#include <cmath>

#include "lrchain/jobs/wave_job.hpp"
#include "lrchain/model.hpp"
#include "../support/exp7_seeded_fate.hpp"

using namespace lrchain;

TEST_CASE("wave fate: a cubic locally resonant chain (not the paper's) passes through experiment 7's dark stage") {
  const double alpha = 1.5, delta0 = 0.27;
  const Model chain = shipped_model("resonant_chain_polynomial",
                                    {{"k1", alpha * std::pow(delta0, alpha - 1)},
                                     {"b1", -alpha * (alpha - 1) / 2 * std::pow(delta0, alpha - 2)},
                                     {"g1", alpha * (alpha - 1) * (alpha - 2) / 6 * std::pow(delta0, alpha - 3)},
                                     {"k2", 1.0},
                                     {"b2", 0.0},
                                     {"g2", 0.0},
                                     {"rho", 0.32}});
  const jobs::wave::WaveResult r = test::exp7_seeded_fate(chain);
  REQUIRE(r.fate);
  const auto& f = *r.fate;
  CHECK(f.strain_deviation);
  CHECK(f.broke_at == doctest::Approx(9619).epsilon(0.1));
  REQUIRE(f.dark_stage.found());
  CHECK(f.dark_stage.from > 28000);
  CHECK(f.dark_stage.from < 31000);
  CHECK(f.dark_stage.until > 36000);
  CHECK(f.dark_stage.until < 41000);
  CHECK(f.dark_stage.width == doctest::Approx(35.1).epsilon(0.15));
  CHECK(f.dark_stage.depth > 0.5);
  CHECK(f.fate == sim::wave::WaveFate::modulated);
}
