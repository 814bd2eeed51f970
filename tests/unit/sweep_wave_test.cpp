// The "wave stability" sweep job: a point's scalars and rows are the wave job's (jobs/wave_job.hpp) for
// the same options, bit for bit; at small amplitude its largest growth rate is the NLS's |h_tilde| A^2/4
// (the modulational instability of a focusing NLS, e.g. Remoissenet, Waves Called Solitons, Ch. 4), to
// the O(A^2) relative error the wave job's own test allows; the paper's chain and a shipped model file
// both work as bases; a point the job refuses is recorded invalid naming [wave]'s key.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"
#include "lrchain/jobs/wave_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "sweep_test_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain;
using namespace lrchain::jobs::sweep;

using lrchain::test::run_sweep_file;
using lrchain::test::sweep_scalar;

TEST_CASE("sweep wave stability: a point is the wave job's result, and the NLS's growth rate at small amplitude" *
          doctest::test_suite("fast")) {
  const fs::path d = lrchain::test::sweep_scratch("sweep-wave", "fput");
  lrchain::test::write_text(d / "base.toml", "experiment = \"wave stability\"\nmodel = \"fput\"\n"
                                             "[wave]\ntheta = 2.5\namplitude = 0.01\nk_points = 40\n");
  lrchain::test::write_text(d / "s.toml", "job = \"wave stability\"\nbase = \"base.toml\"\noutput = \"" +
                                              (d / "s.h5").string() +
                                              "\"\n[[axis]]\nparameter = \"wave.theta\"\nvalues = [2.5, 3.0, 4.0]\n");
  const SweepResults r = run_sweep_file(d / "s.toml");
  const Model fput = shipped_model("fput");
  for (std::size_t p = 0; p < 2; ++p) {
    CAPTURE(p);
    REQUIRE(r.status[p] == std::int8_t(PointStatus::ok));
    jobs::wave::WaveConfig c;
    c.step = jobs::wave::WaveStep::stability;
    c.model = &fput;
    c.kernels = &sim::lattice_kernels_of(fput);
    c.theta = p == 0 ? 2.5 : 3.0;
    c.amplitude = 0.01;
    c.k_points = 40;
    const jobs::wave::WaveResult w = jobs::wave::run(c);
    REQUIRE(w.stability);
    CHECK(sweep_scalar(r, "omega", p) == w.waves.back().omega);
    CHECK(sweep_scalar(r, "largest_rate", p) == w.stability->largest_rate);
    CHECK(sweep_scalar(r, "stable", p) == 0);
    CHECK(sweep_scalar(r, "unstable_bands", p) == double(w.stability->bands.size()));
    REQUIRE(r.rows[p].size() == 4 * w.stability->bands.size());
    CHECK(r.rows[p][2] == w.stability->bands.front().largest_rate);
    // fput is focusing at these theta; |rate / (|h_tilde| A^2/4) - 1| was 1.3e-4 at theta = 2.5
    CHECK(sweep_scalar(r, "focusing", p) == 1);
    CHECK(std::abs(sweep_scalar(r, "largest_rate", p) / sweep_scalar(r, "nls_largest_rate", p) - 1) < 1e-3);
  }
  // theta = 4 is outside (-pi, pi]: invalid, with the key as [wave] names it
  CHECK(r.status[2] == std::int8_t(PointStatus::invalid));
  CHECK(r.reasons[2].find("[wave] theta") != std::string::npos);
  fs::remove_all(d);
}

TEST_CASE("sweep wave stability: the paper's chain with [model] as the base" * doctest::test_suite("fast")) {
  const fs::path d = lrchain::test::sweep_scratch("sweep-wave", "chain");
  lrchain::test::write_text(d / "base.toml", "experiment = \"wave stability\"\n[model]\nrho = \"1/3\"\n"
                                             "[wave]\nbranch = \"optical\"\ntheta = 1.5707963267948966\n"
                                             "amplitude = 0.01\nk_points = 20\n");
  lrchain::test::write_text(d / "s.toml", "job = \"wave stability\"\nbase = \"base.toml\"\noutput = \"" +
                                              (d / "s.h5").string() +
                                              "\"\n[[axis]]\nparameter = \"model.rho\"\nvalues = [0.3333333333333333, 1]\n");
  const SweepResults r = run_sweep_file(d / "s.toml");
  for (std::size_t p = 0; p < 2; ++p) {
    CAPTURE(p);
    REQUIRE(r.status[p] == std::int8_t(PointStatus::ok));
    // the wave's frequency shift is the NLS's h A^2/4 to O(A^4): 1e-3 relative at A = 0.01
    CHECK(std::abs(sweep_scalar(r, "omega_shift", p) / sweep_scalar(r, "nls_omega_shift", p) - 1) < 1e-3);
  }
  CHECK(sweep_scalar(r, "omega_linear", 0) != sweep_scalar(r, "omega_linear", 1));  // rho is the point's
  fs::remove_all(d);
}
