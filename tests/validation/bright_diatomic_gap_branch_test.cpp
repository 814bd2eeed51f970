// The light-bead-centred gap breather of the diatomic granular chain continued through the gap
// (docs/bright-breathers.md, "Gap breathers of the diatomic granular chain"): free of real Floquet
// multipliers deep in the gap, really unstable near the optical edge, the change located on the branch.
// About 55 s (31 sites, 26 points).
#include <doctest/doctest.h>

#include <string>

#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::bright_breather;

TEST_CASE("bright: diatomic light-bead gap breather gains a real instability at omega_b = 1.3468") {
  // Theocharis et al., Phys. Rev. E 82, 056604 (2010): the light-bead-centred family is the potentially
  // stable one; lrchain finds it without a real multiplier from omega_b = 1.1 up to a threshold where a
  // real pair leaves +1. Expected 1.3468: located on rings of 41 sites (1.34682, continued from 1.1 up)
  // and of 61 sites (1.34660, continued from 1.39 down), independent runs from opposite ends.
  const Model model = shipped_model("diatomic_chain", {});
  BrightBreatherConfig c;
  c.step = BrightStep::branch;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("diatomic_chain");
  c.omega_b = 1.1;
  c.center = "site";
  c.sites = 31;
  c.tail_tolerance = 5e-3;  // 31 sites: the breather near 1.36 has decayed to 2e-3 of its peak on the far quarter
  c.points = 60;
  c.ds = 0.3;
  c.to = 1.36;
  validate(c);
  const BrightBreatherResult r = run(c);
  REQUIRE(!failure(r));
  REQUIRE(r.branch_floquets.size() == r.branch.points.size());
  CHECK(r.branch.points.back().parameter == doctest::Approx(1.36));
  int thresholds = 0;
  double threshold = 0;
  for (const auto& b : r.bifurcations)
    if (b.kind == "branch_point") {
      ++thresholds;
      threshold = b.omega_b;
      CHECK(b.located);
      CHECK(b.location_error < 1e-5);
    }
  REQUIRE(thresholds == 1);
  CHECK(threshold == doctest::Approx(1.3468).epsilon(5e-4));
  for (std::size_t k = 0; k < r.branch.points.size(); ++k) {
    INFO("omega_b = ", r.branch.points[k].parameter);
    CHECK(r.branch_floquets[k].multipliers.real_instability == (r.branch.points[k].parameter > threshold));
  }
  // The last point, omega_b = 1.36: real multiplier 1.319 measured (1.31-1.34 on the 41-site branch there).
  CHECK(r.branch_floquets.back().multipliers.max_real > 1.2);
}
