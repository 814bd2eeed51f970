// Windowed Floquet multipliers of dark breathers (sim/dark/windowed_dark_floquet.hpp) against dense
// monodromies: the localized multipliers of a dip's window certified on the full ring agree with the
// whole ring's dense ones to 1e-8; the background's Floquet-Bloch multipliers with the dense monodromy
// of a ring carrying the plane wave alone.
#include <doctest/doctest.h>

#include <algorithm>
#include <complex>
#include <limits>

#include <Eigen/Eigenvalues>

#include "../support/nearest_multiplier.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/dark/contact_bonds.hpp"
#include "lrchain/sim/dark/windowed_dark_floquet.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

using namespace lrchain;
using lrchain::test::nearest;

namespace {

// The dense dark job's breather and multipliers (a theta = pi edge of the shipped model).
jobs::dark::DarkResult dense_dark(const Model& model, const char* name, const char* branch, const char* center,
                                  double omega_b, Index sites) {
  jobs::dark::DarkConfig c;
  c.step = jobs::dark::DarkStep::floquet;
  c.model = &model;
  c.kernels = sim::shipped_lattice_kernels(name);
  c.branch = branch;
  c.center = center;
  c.omega_b = omega_b;
  c.sites = sites;
  c.krylov.solver = "dense";
  jobs::dark::validate(c);
  jobs::dark::DarkResult r = jobs::dark::run(c);
  REQUIRE(!jobs::dark::failure(r));
  REQUIRE(r.floquet);
  return r;
}

}  // namespace

TEST_CASE("windowed dark floquet: a klein_gordon dark breather's localized real instability from its dip's window" *
          doctest::test_suite("fast")) {
  // klein_gordon at b = -1/2 (defocusing at theta = pi, edge 1.1832), a bond-centred dark breather at
  // omega_b = 1.0 on 201 sites: the whole ring's dense monodromy has a real multiplier 2.0324 (the dip's
  // translation mode, pinned by the lattice) and its inverse.
  const Model model = shipped_model("klein_gordon", {{"b", -0.5}});
  const auto dense = dense_dark(model, "klein_gordon", "", "bond", 1.0, 201);
  const lrchain_lattice_kernels* kernels = sim::shipped_lattice_kernels("klein_gordon");
  const std::vector<double> parameters = sim::lattice_parameters(model);
  const sim::dark::DarkShooting shooting(*kernels, parameters, 201, false, sim::dark::ShootingMode::reversible);
  const sim::dark::WindowedDarkFloquet r =
      sim::dark::windowed_dark_floquet(shooting, {kernels, parameters, false, {}}, dense.z0, 1.0);
  CHECK(r.window.sites < 201);
  CHECK(r.window.trivial.size() == 2);
  // The plane wave of a defocusing edge: its Floquet-Bloch multipliers on the unit circle.
  REQUIRE(r.background.reason.empty());
  CHECK(!r.background.unstable);
  CHECK(r.background.max_modulus <= 1 + 1e-6);
  CHECK(r.background.ring_residual <= 1e-8);
  REQUIRE(r.window.localized.size() >= 2);
  CHECK(std::abs(r.window.localized.front().lambda - 2.0324) <= 1e-4);
  Index certified = 0;
  for (const auto& m : r.window.localized) {
    if (!m.certified) continue;
    ++certified;
    CHECK(*m.residual <= 1e-8);
    CHECK(nearest(m.lambda, dense.floquet->multipliers) <= 1e-8);  // the whole ring's own
  }
  CHECK(certified >= 2);
  CHECK(r.window.localized.front().certified);
  REQUIRE(r.verdict);
  CHECK(r.verdict->kind() == "real");
}

TEST_CASE("windowed dark floquet: the resonant chain's background is parametrically unstable at omega_b = 2.42" *
          doctest::test_suite("fast")) {
  // The paper's chain (rho = 1/3, optical, site-centred) at omega_b = 2.42 on 41 sites. The background
  // plane wave's Floquet-Bloch multipliers leave the unit circle (largest at the 2-site cell's zone
  // boundary, which a ring of 64 sites samples): they are checked against the dense monodromy of a
  // 64-site ring carrying the plane wave alone, and give the verdict.
  const Model model = shipped_model("resonant_chain", {});
  const auto dense = dense_dark(model, "resonant_chain", "optical", "site", 2.42, 41);
  const lrchain_lattice_kernels* kernels = sim::shipped_lattice_kernels("resonant_chain");
  const std::vector<double> parameters = sim::lattice_parameters(model);
  const sim::dark::ContactBonds contacts = sim::dark::model_contact_bonds(*kernels, parameters, true);
  const sim::dark::DarkShooting shooting(*kernels, parameters, 41, true, sim::dark::ShootingMode::reversible, {},
                                         contacts);
  const sim::dark::WindowedDarkFloquet r =
      sim::dark::windowed_dark_floquet(shooting, {kernels, parameters, true, contacts}, dense.z0, 2.42);
  REQUIRE(r.background.reason.empty());
  REQUIRE(r.background.unstable);
  CHECK(r.background.ring_residual <= 1e-8);
  // The plane wave alone on 64 sites, its dense monodromy.
  const Index ring = 64, fields = r.background.cell.rows();
  Eigen::VectorXd wave(fields * ring);
  for (Index f = 0; f < fields; ++f)
    for (Index i = 0; i < ring; ++i) wave[f * ring + i] = r.background.cell(f, i % 2);
  const sim::dark::DarkShooting background(*kernels, parameters, ring, true, sim::dark::ShootingMode::reversible, {},
                                           contacts);
  Eigen::EigenSolver<Eigen::MatrixXd> solver(background.monodromy(wave, 2.42), false);
  const double dense_max = solver.eigenvalues().cwiseAbs().maxCoeff();
  CHECK(std::abs(std::abs(r.background.ring_leading) - dense_max) <= 1e-8);
  CHECK(std::abs(r.background.max_modulus - dense_max) <= 1e-8);
  CHECK(dense_max > 1.1);
  REQUIRE(r.verdict);
  CHECK(r.verdict->kind() != "stable");
}
