// Gap breathers of the diatomic granular chain (models/diatomic_chain.toml) through the bright-breather
// job: the heavy-bead-centred and light-bead-centred families deep in the gap (1, sqrt 2) and their
// Floquet stability, against Theocharis, Boechler, Kevrekidis, Job, Porter & Daraio, Phys. Rev. E 82,
// 056604 (2010), arXiv:1009.0885 (docs/bright-breathers.md, "Gap breathers of the diatomic chain").
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::bright_breather;

namespace {

// The Floquet step on the shipped diatomic chain (light beads u of mass 1, heavy beads v of mass m = 2).
BrightBreatherResult diatomic_floquet(double omega_b, Index sites, const char* center) {
  static const Model model = shipped_model("diatomic_chain", {});
  BrightBreatherConfig c;
  c.step = BrightStep::floquet;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels("diatomic_chain");
  c.omega_b = omega_b;
  c.sites = sites;
  c.center = center;
  validate(c);
  BrightBreatherResult r = run(c);
  INFO(failure(r).value_or(""));
  REQUIRE(!failure(r));
  REQUIRE(r.floquet);
  return r;
}

// The contact strains in the order of the chain, from Z(0) = (r, w1) in strain form: bond 2n joins
// u[n] and v[n] (w1[n] = v[n] - u[n]), bond 2n + 1 joins v[n] and u[n + 1] (r[n + 1] - w1[n]).
std::vector<double> bond_strains(const BrightBreatherResult& r) {
  const Index sites = r.config.sites;
  std::vector<double> bonds;
  for (Index i = 0; i + 1 < sites; ++i) {
    bonds.push_back(r.z0(sites + i));
    bonds.push_back(r.z0(i + 1) - r.z0(sites + i));
  }
  return bonds;
}

// max_j |b[centre + j] - b[centre - j]| / max |b|: 0 for a profile mirror-symmetric about the bead
// between bonds centre - 1/2 and centre + 1/2 (`centre` a half-integer bond index, given doubled).
double mirror_defect(const std::vector<double>& b, Index doubled_centre) {
  double defect = 0, peak = 0;
  for (const double x : b) peak = std::max(peak, std::abs(x));
  for (Index j = 1; j <= 9; j += 2)
    defect = std::max(defect, std::abs(b[std::size_t((doubled_centre + j) / 2)] - b[std::size_t((doubled_centre - j) / 2)]));
  return defect / peak;
}

}  // namespace

TEST_CASE("bright job: diatomic gap breathers, heavy-centred unstable, light-centred without real instability" *
          doctest::test_suite("fast")) {
  // Theocharis et al. (2010), abstract: the gap breather centred on a heavy bead has a
  // symmetric profile and is unstable; the one centred on a light bead has an asymmetric profile and is
  // "potentially stable". At omega_b = 1.1, deep in the gap (1, sqrt 2) of m = 2 (their strongly
  // discrete regime), --center bond (the NLS envelope symmetric about v[0]) converges to the heavy-bead
  // family and --center site (the envelope peaked on u[0]) to the light-bead family.
  const BrightBreatherResult heavy = diatomic_floquet(1.1, 31, "bond");
  const std::vector<double> hb = bond_strains(heavy);
  const Index cell = (heavy.config.sites - 1) / 2;
  // v[0] sits between bonds 2 cell and 2 cell + 1: doubled half-integer index 4 cell + 1.
  CHECK(mirror_defect(hb, 4 * cell + 1) < 1e-8);
  CHECK(heavy.floquet->multipliers.real_instability);
  // A localized real instability: 3.5138 measured here on rings of 31, 41 and 81 sites alike
  // (`lrchain bright floquet --model diatomic_chain --omega-b 1.1 --center bond --sites 81`), so no
  // finite-ring effect.
  CHECK(heavy.floquet->multipliers.max_real == doctest::Approx(3.5138).epsilon(1e-3));

  const BrightBreatherResult light = diatomic_floquet(1.1, 31, "site");
  const std::vector<double> lb = bond_strains(light);
  // u[0] sits between bonds 2 cell - 1 and 2 cell: doubled index 4 cell - 1. The contact on its left
  // opens (strain 1.53 > delta0 = 4/9), the one on its right stays closed (-0.65): no mirror symmetry.
  CHECK(mirror_defect(lb, 4 * cell - 1) > 0.5);
  CHECK(lb[std::size_t(2 * cell - 1)] > 4.0 / 9.0);
  CHECK(lb[std::size_t(2 * cell)] < 0);
  // No real instability: only a weak oscillatory one whose size follows the ring (1.037 on 31 sites,
  // 1.052 on 41, 1.027 on 81: collisions with the ring's discrete phonons), never the heavy family's 3.5.
  CHECK_FALSE(light.floquet->multipliers.real_instability);
  CHECK(light.floquet->max_nontrivial_modulus < 1.06);
}
