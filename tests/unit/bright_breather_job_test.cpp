// The exact bright-breather job through the library (lrchain/jobs/bright_breather_job.hpp): the NLS
// limit on klein_gordon, two classical results (the FPU chain's stable Page and unstable
// Sievers-Takeno modes; the Klein-Gordon anti-continuum limit), the refusals, the localization check and
// the Floquet multipliers of a stable breather. The `lrchain bright` argv mapping: bright_cli_test.cpp.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>

#include "../support/oscillator_amplitude.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::jobs::bright_breather;

namespace {

// A shipped model with its compiled-in lattice kernels.
struct Lattice {
  Model model;
  const lrchain_lattice_kernels* kernels;
  Lattice(const char* name, const std::vector<std::pair<std::string, double>>& values = {})
      : model(shipped_model(name, values)), kernels(sim::shipped_lattice_kernels(name)) {}
  BrightBreatherConfig config(BrightStep step, double omega_b, Index sites, const char* center = "site") const {
    BrightBreatherConfig c;
    c.step = step;
    c.model = &model;
    c.kernels = kernels;
    c.omega_b = omega_b;
    c.sites = sites;
    c.center = center;
    return c;
  }
};

// validate(c) then run(c), requiring a localized breather.
BrightBreatherResult solved(const BrightBreatherConfig& c) {
  validate(c);
  BrightBreatherResult r = run(c);
  INFO(failure(r).value_or(""));
  REQUIRE(!failure(r));
  return r;
}

// The refusal of validate(c): "key: message", or "" when it accepts c.
std::string refusal(const BrightBreatherConfig& c) {
  try {
    validate(c);
  } catch (const InvalidParameter& e) {
    return e.parameter() + ": " + e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("bright job: the klein_gordon breather tends to the NLS seed linearly in the detuning" * doctest::test_suite("fast")) {
  // klein_gordon defaults (C = 1/10, w0 = 1, a = 1/4, b = 1/2): the top of the band omega(pi) =
  // sqrt(1 + 4 C) is focusing (omega'' = -0.0845, h_tilde = 0.540), breathers above it. The seed has the
  // second-order terms, so it misses the exact profile by O(epsilon^2) = O(detuning): D / detuning
  // stays constant (measured 3.06, 3.26, 3.18) and D halves with the detuning.
  const Lattice kg("klein_gordon");
  const double edge = std::sqrt(1.4);
  std::vector<double> D, amplitude, width;
  for (const double detuning : {0.01, 0.005, 0.0025}) {
    const BrightBreatherResult r = solved(kg.config(BrightStep::solve, edge + detuning, 121));
    CHECK(r.edge.nls.omega == doctest::Approx(edge).epsilon(1e-12));
    CHECK(r.edge.theta == doctest::Approx(std::numbers::pi));
    CHECK(r.newton.history.back().residual <= 1e-11);
    CHECK(r.profile.localized);
    CHECK(std::abs(r.profile.peak_site - 60) <= 1);  // the mean offset (a = 1/4) can tip |u| to a neighbour
    D.push_back(r.seed_difference);
    amplitude.push_back(std::abs(r.profile.peak - r.seed_profile.peak) / r.profile.peak);
    width.push_back(std::abs(r.profile.width - r.seed_profile.width) / r.profile.width);
    CHECK(r.seed_difference / detuning == doctest::Approx(3.2).epsilon(0.1));
  }
  for (std::size_t k = 0; k + 1 < D.size(); ++k) {
    CHECK(D[k] / D[k + 1] >= 1.7);
    CHECK(D[k] / D[k + 1] <= 2.4);
    CHECK(amplitude[k + 1] < amplitude[k]);  // the amplitude and width approach the NLS prediction too
    CHECK(width[k + 1] < width[k]);
  }
  CHECK(amplitude.back() < 2e-3);
  CHECK(width.back() < 1.5e-2);
}

TEST_CASE("bright job: FPU Page mode stable, Sievers-Takeno mode unstable" * doctest::test_suite("fast")) {
  // Sandusky, Page & Schmidt, Phys. Rev. B 46, 6161 (1992): in the FPU chain with a hard quartic force,
  // the bond-centred (Page) breather above the phonon band is linearly stable, the site-centred
  // (Sievers-Takeno) one has a real unstable multiplier. fput with a = 0, b = 1/2: F(r) = r + r^3/2.
  const Lattice fpu("fput", {{"a", 0.0}});
  const BrightBreatherResult page = solved(fpu.config(BrightStep::floquet, 2.2, 41, "bond"));
  REQUIRE(page.floquet);
  CHECK(page.edge.mean_flow);
  CHECK(page.floquet->trivial_expected == 4);
  CHECK(page.floquet->trivial_found);
  CHECK(page.floquet->stable);
  CHECK(page.floquet->unit_circle_defect <= 1e-8);
  const BrightBreatherResult st = solved(fpu.config(BrightStep::floquet, 2.2, 41, "site"));
  REQUIRE(st.floquet);
  CHECK(st.floquet->trivial_found);
  CHECK_FALSE(st.floquet->stable);
  CHECK(st.floquet->multipliers.real_instability);
  CHECK(st.floquet->max_nontrivial_modulus > 1.01);  // measured 1.0282
  // The Page mode's two largest strains are equal and opposite (r at the centre bond, u_0 = -u_1).
  CHECK(page.profile.peak == doctest::Approx(page.z0.cwiseAbs().maxCoeff()));
}

TEST_CASE("bright job: Klein-Gordon anti-continuum limit, one oscillator at omega_b" * doctest::test_suite("fast")) {
  // MacKay & Aubry, Nonlinearity 7, 1623 (1994): as the coupling C -> 0 the breather tends to one
  // excited oscillator x'' + w0^2 x + b x^3 = 0 at frequency omega_b, the others at rest; the centre's
  // amplitude differs from that oscillator's by O(C). Its amplitude comes from the period integral
  // (oscillator_amplitude), independent of the lattice code.
  const double omega_b = 1.1, A = lrchain::test::oscillator_amplitude(1.0, 0.5, omega_b);
  CHECK(A == doctest::Approx(0.751).epsilon(2e-3));
  std::vector<double> difference;
  for (const double C : {0.004, 0.002, 0.001}) {
    const Lattice kg("klein_gordon", {{"C", C}, {"a", 0.0}});
    const BrightBreatherResult r = solved(kg.config(BrightStep::solve, omega_b, 21));
    difference.push_back(std::abs(r.profile.peak - A) / A);
    CHECK(difference.back() < 5 * C);
    CHECK(r.z0.cwiseAbs().maxCoeff() == doctest::Approx(r.profile.peak));
  }
  CHECK(difference[0] / difference[1] == doctest::Approx(2).epsilon(0.15));
  CHECK(difference[1] / difference[2] == doctest::Approx(2).epsilon(0.15));
}

TEST_CASE("bright job: validate refuses a frequency in a band, a resonant harmonic, no focusing edge" * doctest::test_suite("fast")) {
  const Lattice kg("klein_gordon");  // band [1, sqrt(1.4) = 1.1832]
  CHECK(refusal(kg.config(BrightStep::solve, 1.19, 61)) == "");
  const std::string in_band = refusal(kg.config(BrightStep::solve, 1.1, 61));
  CHECK(in_band.rfind("omega_b: ", 0) == 0);
  CHECK(in_band.find("inside the linear band of branch branch0, [1, 1.183215957]") != std::string::npos);
  // Far beyond the bands (10 x 1.1832 = 11.83) the NLS seed means nothing: refused, not solved.
  CHECK(refusal(kg.config(BrightStep::solve, 12, 61)).find("omega_b: invalid omega_b: must be at most 10 times") == 0);
  // C = 1: band [1, sqrt(5) = 2.236]; a soft breather below it at 0.97 has 2 omega_b = 1.94 inside.
  const Lattice wide("klein_gordon", {{"C", 1.0}, {"a", 0.0}, {"b", -0.5}});
  const std::string harmonic = refusal(wide.config(BrightStep::solve, 0.97, 61));
  CHECK(harmonic.rfind("omega_b: ", 0) == 0);
  CHECK(harmonic.find("harmonic 2 omega_b = 1.94 lies inside the linear band") != std::string::npos);
  // The same model with C = 1/10: band [1, 1.1832], 2 omega_b above it, theta = 0 focusing (b < 0).
  const Lattice soft("klein_gordon", {{"a", 0.0}, {"b", -0.5}});
  CHECK(refusal(soft.config(BrightStep::solve, 0.97, 61)) == "");
  CHECK(refusal(soft.config(BrightStep::solve, 1.19, 61)).find("no focusing band edge") != std::string::npos);
  // The paper's chain: every band edge is defocusing (its stationary breathers at an edge are dark).
  const Lattice chain("resonant_chain");
  CHECK(refusal(chain.config(BrightStep::solve, 2.5, 61)).find("optical at theta = pi: defocusing") != std::string::npos);
  BrightBreatherConfig c = kg.config(BrightStep::solve, 1.19, 60);
  CHECK(refusal(c).rfind("sites: ", 0) == 0);
  c.sites = 61;
  c.center = "middle";
  CHECK(refusal(c).rfind("center: ", 0) == 0);
  c.center = "bond";
  c.tail_tolerance = 0;
  CHECK(refusal(c).rfind("tail_tolerance: ", 0) == 0);
  c.tail_tolerance = 1e-3;
  c.branch = "optical";
  CHECK(refusal(c).rfind("branch: ", 0) == 0);
}

TEST_CASE("bright job: a converged zero that does not decay on the ring is no bright breather" * doctest::test_suite("fast")) {
  // fput (a = 0) at omega_b = 2.05: width 1/a = 2.2 sites of the seed but slow tails; 41 sites leave
  // 2.2e-3 of the peak on the far quarter (measured), over the 1e-3 allowed: rejected, not reported as a breather.
  const Lattice fpu("fput", {{"a", 0.0}});
  const BrightBreatherResult r = run(fpu.config(BrightStep::floquet, 2.05, 41));
  CHECK(r.newton.converged);
  CHECK_FALSE(r.profile.localized);
  CHECK_FALSE(r.floquet);
  REQUIRE(failure(r));
  CHECK(failure(r)->find("not localized") != std::string::npos);
  CHECK(to_json(r)["failure"]["kind"] == "not_a_bright_breather");
}

TEST_CASE("bright job: a stable breather's multipliers lie on the unit circle, the trivial +1 pair found" * doctest::test_suite("fast")) {
  // klein_gordon (on-site: no mean flow, one trivial pair), site-centred above the band: stable.
  const Lattice kg("klein_gordon");
  const BrightBreatherResult r = solved(kg.config(BrightStep::floquet, 1.19, 61));
  REQUIRE(r.floquet);
  const auto& f = *r.floquet;
  CHECK(f.multipliers.multipliers.size() == 2 * 61);
  CHECK(f.trivial_expected == 2);
  CHECK(f.trivial_found);
  CHECK(f.trivial.size() == 2);
  CHECK(f.trivial_distance <= 1e-5);  // a Jordan block: the pair splits by ~sqrt(rounding)
  CHECK(f.stable);
  CHECK(f.unit_circle_defect <= 1e-8);
  CHECK(f.multipliers.pairing_defect <= 1e-8);
  CHECK(f.det_defect <= 1e-8);
  // The bond-centred family of the same lattice is unstable.
  const BrightBreatherResult bond = solved(kg.config(BrightStep::floquet, 1.19, 61, "bond"));
  CHECK_FALSE(bond.floquet->stable);
  CHECK(bond.floquet->trivial_found);
}

TEST_CASE("bright job: continuation in omega_b away from the edge, within the non-resonant window" * doctest::test_suite("fast")) {
  // klein_gordon above its band (h_tilde > 0): omega_b rises from 1.19, the breather grows and narrows
  // and stays stable (the site-centred family, as at 1.19); the window is (edge, none above: 2 omega_b
  // is above the band already).
  const Lattice kg("klein_gordon");
  BrightBreatherConfig c = kg.config(BrightStep::branch, 1.19, 61);
  c.points = 6;
  const BrightBreatherResult r = solved(c);
  REQUIRE(r.branch.points.size() == 6);
  CHECK(r.branch.stop_reason == "reached 6 points");
  CHECK(r.window_low == doctest::Approx(std::sqrt(1.4)).epsilon(1e-12));
  CHECK(std::isinf(r.window_high));
  CHECK(r.branch.points.front().omega_b == 1.19);
  REQUIRE(r.branch_floquets.size() == 6);
  for (std::size_t k = 1; k < 6; ++k) {
    CHECK(r.branch.points[k].omega_b > r.branch.points[k - 1].omega_b);
    CHECK(r.branch_profiles[k].peak > r.branch_profiles[k - 1].peak);
    CHECK(r.branch_profiles[k].width < r.branch_profiles[k - 1].width);
    CHECK(r.branch.points[k].residual <= 1e-11);
    CHECK(r.branch_floquets[k].stable);
  }
  // Monotone in omega_b and stable throughout: no fold, no multiplier crossing (branch_bifurcations.hpp).
  CHECK(r.bifurcations.empty());
  // Krein signatures: away from the breather the ring is the linear chain, whose phonons
  // (omega_q in [1, sqrt(1.4)], positive energy) give multipliers exp(i omega_q T_b); with
  // omega_q T_b in (pi, 2 pi) the one on the upper circle is exp(-i omega_q T_b), at angle
  // 2 pi (1 - omega_q / omega_b) in [2 pi (1 - sqrt(1.4)/1.19), 2 pi (1 - 1/1.19)] = [0.0356, 1.0029],
  // with signature -1 (the conjugate of a positive one). The trivial pair is left out; one multiplier
  // outside the arc, near +1, is the breather's own pinning mode (its translation along the lattice).
  REQUIRE(r.branch_krein.size() == 6);
  const auto& krein = r.branch_krein.front();
  std::size_t in_arc = 0;
  for (const auto& m : krein) {
    const double angle = std::arg(m.lambda);
    if (angle >= 2 * M_PI * (1 - std::sqrt(1.4) / 1.19) - 1e-6 && angle <= 2 * M_PI * (1 - 1 / 1.19) + 1e-6) ++in_arc;
    CHECK(m.signature == -1);
  }
  CHECK(in_arc >= 55);
  CHECK(krein.size() - in_arc <= 1);
  // Below the band of the soft lattice (h_tilde < 0) the window ends where 2 omega_b meets the band
  // top sqrt(1.4): (sqrt(1.4)/2, 1).
  const Lattice soft("klein_gordon", {{"a", 0.0}, {"b", -0.5}});
  BrightBreatherConfig s = soft.config(BrightStep::branch, 0.97, 41);
  s.points = 2;
  s.branch_floquet = false;
  const BrightBreatherResult below = solved(s);
  CHECK(below.window_low == doctest::Approx(std::sqrt(1.4) / 2).epsilon(1e-12));
  CHECK(below.window_high == doctest::Approx(1.0).epsilon(1e-12));
  REQUIRE(below.branch.points.size() == 2);
  CHECK(below.branch.points[1].omega_b < 0.97);
  CHECK(below.branch_floquets.empty());
}
