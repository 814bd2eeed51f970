// Period tripling along a bright branch and multiplier crossings located by bisection
// (sim/bright/branch_bifurcations.hpp: multipliers_beyond_two_thirds, locate_crossing), on monodromy
// matrices whose crossing is known by construction and on a real klein_gordon branch.
#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>
#include <doctest/doctest.h>

#include <Eigen/Dense>

#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/bright/branch_bifurcations.hpp"
#include "lrchain/sim/model_lattice.hpp"

using namespace lrchain;
using namespace lrchain::sim::bright;

namespace {

constexpr double two_thirds_pi = 2 * std::numbers::pi / 3;

// A symplectic monodromy: the trivial Jordan block at +1 and one 2 x 2 block.
Eigen::MatrixXd with_trivial_block(const Eigen::Matrix2d& block) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(4, 4);
  m.block(0, 0, 2, 2) << 1, 1, 0, 1;
  m.block(2, 2, 2, 2) = block;
  return m;
}

Eigen::Matrix2d rotation(double angle) {
  Eigen::Matrix2d r;
  r << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return r;
}

// Where (|lambda| - 1)^2, linear in the parameter past a Hamiltonian-Hopf (Krein) collision, vanishes:
// the line through (p1, |lambda1|) and (p2, |lambda2|).
double hopf_onset(double p1, double modulus1, double p2, double modulus2) {
  const double r1 = (modulus1 - 1) * (modulus1 - 1), r2 = (modulus2 - 1) * (modulus2 - 1);
  return (p1 * r2 - p2 * r1) / (r2 - r1);
}

// The branch step of the bright job on klein_gordon (31 sites, site-centred) from omega_b, with the
// given coupling C; `adjust` sets the rest (points, ds, a continued parameter).
template <class Adjust>
jobs::bright_breather::BrightBreatherConfig klein_gordon_branch(const Model& kg, double omega_b, Adjust adjust) {
  jobs::bright_breather::BrightBreatherConfig c;
  c.step = jobs::bright_breather::BrightStep::branch;
  c.model = &kg;
  c.kernels = sim::shipped_lattice_kernels("klein_gordon");
  c.omega_b = omega_b;
  c.sites = 31;
  adjust(c);
  jobs::bright_breather::validate(c);
  return c;
}

// The first bifurcation of that kind in r (REQUIREd to exist).
const BranchBifurcation& first_of_kind(const jobs::bright_breather::BrightBreatherResult& r, const std::string& kind) {
  const auto it = std::find_if(r.bifurcations.begin(), r.bifurcations.end(),
                               [&](const BranchBifurcation& b) { return b.kind == kind; });
  REQUIRE(it != r.bifurcations.end());
  return *it;
}
}  // namespace

TEST_CASE("bright branch: multipliers past exp(+-2 pi i/3) counted, a change flagged as period tripling" * doctest::test_suite("fast")) {
  // A rotation by 2.5 rad (> 2 pi/3 = 2.094) puts exp(+-2.5 i) in the sector |arg| > 2 pi/3: both
  // counted; by 1 rad: none; a real pair (-3, -1/3): both (arg = pi); the trivial +1 pair never.
  CHECK(multipliers_beyond_two_thirds(bright_floquet(with_trivial_block(rotation(2.5)), false)) == 2);
  CHECK(multipliers_beyond_two_thirds(bright_floquet(with_trivial_block(rotation(1.0)), false)) == 0);
  CHECK(multipliers_beyond_two_thirds(bright_floquet(with_trivial_block(Eigen::Vector2d(-3, -1.0 / 3).asDiagonal()), false)) == 2);
  // Samples 0 -> 2 -> 2 in the sector: one period tripling, between the first two points, bracketed.
  const std::vector<BranchSample> samples{{0.0, 1.0, 1.0, 1.0, 0, 0, false, 0},
                                          {0.1, 1.1, 1.0, 2.0, 0, 0, false, 2},
                                          {0.2, 1.2, 1.0, 3.0, 0, 0, false, 2}};
  const std::vector<BranchBifurcation> found = branch_bifurcations(samples);
  REQUIRE(found.size() == 1);
  CHECK(found[0].kind == "period_tripling");
  CHECK(found[0].index == 0);
  CHECK(found[0].omega_b == doctest::Approx(1.05).epsilon(1e-14));
  CHECK_FALSE(found[0].located);
}

TEST_CASE("bright branch: a period tripling and a branch point located by bisection" * doctest::test_suite("fast")) {
  // Period tripling: the block rotates by omega_b rad, so its multiplier passes exp(2 pi i/3) at omega_b
  // = 2 pi/3 exactly. Z(0) is the one-component vector (omega_b): the solver checks it is handed the
  // guess interpolated linearly between the bracket's ends, which is then exact.
  int solves = 0;
  double worst_guess = 0;
  const CrossingSolver tripling = [&](double w, const Eigen::VectorXd& guess) -> std::optional<CrossingSolution> {
    ++solves;
    worst_guess = std::max(worst_guess, std::abs(guess(0) - w));
    return CrossingSolution{Eigen::VectorXd::Constant(1, w), bright_floquet(with_trivial_block(rotation(w)), false), w};
  };
  BranchBifurcation b{"period_tripling", 0, 2.1, 0, 2.0, 2.2, false, 0, std::nullopt};
  locate_crossing(b, 2.0, Eigen::VectorXd::Constant(1, 2.0), bright_floquet(with_trivial_block(rotation(2.0)), false), 2.2,
                  Eigen::VectorXd::Constant(1, 2.2), bright_floquet(with_trivial_block(rotation(2.2)), false), tripling,
                  1e-6, 1e-9);
  REQUIRE(b.located);
  CHECK(std::abs(b.omega_b - two_thirds_pi) <= b.location_error);
  CHECK(b.location_error <= 0.5e-9);
  CHECK(solves == 28);  // 0.2 / 2^28 < 1e-9 <= 0.2 / 2^27
  CHECK(worst_guess <= 1e-15);
  REQUIRE(b.multiplier);
  CHECK(std::abs(*b.multiplier - std::polar(1.0, two_thirds_pi)) <= 1e-9);  // |d lambda / d omega_b| = 1
  CHECK(b.omega_low == 2.0);  // the branch points' bracket stays
  CHECK(b.omega_high == 2.2);

  // Branch point: a pair on the circle at angle sqrt(w* - w) below w* = 1.2345 meets at +1 and leaves
  // as (e^mu, e^-mu), mu = sqrt(w - w*), above: the count beyond 1 + 1e-6 changes once mu > 1e-6, i.e.
  // within 1e-12 of w*, far inside the bisection's 1e-8.
  const double w_star = 1.2345;
  const auto block = [&](double w) -> Eigen::Matrix2d {
    if (w <= w_star) return rotation(std::sqrt(w_star - w));
    const double mu = std::sqrt(w - w_star);
    return Eigen::Vector2d(std::exp(mu), std::exp(-mu)).asDiagonal();
  };
  const CrossingSolver branch = [&](double w, const Eigen::VectorXd&) -> std::optional<CrossingSolution> {
    return CrossingSolution{Eigen::VectorXd::Constant(1, w), bright_floquet(with_trivial_block(block(w)), false), w};
  };
  BranchBifurcation p{"branch_point", 3, 1.25, 0, 1.2, 1.3, false, 0, std::nullopt};
  locate_crossing(p, 1.2, Eigen::VectorXd::Constant(1, 1.2), bright_floquet(with_trivial_block(block(1.2)), false), 1.3,
                  Eigen::VectorXd::Constant(1, 1.3), bright_floquet(with_trivial_block(block(1.3)), false), branch, 1e-6,
                  1e-8);
  REQUIRE(p.located);
  CHECK(std::abs(p.omega_b - w_star) <= p.location_error + 1e-12);
  REQUIRE(p.multiplier);
  CHECK(p.multiplier->real() > 1);  // the real multiplier just past +1, e^sqrt(w - w*) with w - w* < 1e-8
  CHECK(p.multiplier->real() < 1 + 2e-4);

  // A re-solve that fails leaves the bracket as it was.
  BranchBifurcation q{"branch_point", 3, 1.25, 0, 1.2, 1.3, false, 0, std::nullopt};
  locate_crossing(q, 1.2, Eigen::VectorXd::Constant(1, 1.2), bright_floquet(with_trivial_block(block(1.2)), false), 1.3,
                  Eigen::VectorXd::Constant(1, 1.3), bright_floquet(with_trivial_block(block(1.3)), false),
                  [](double, const Eigen::VectorXd&) { return std::optional<CrossingSolution>(); }, 1e-6, 1e-8);
  CHECK_FALSE(q.located);
  CHECK(q.omega_b == 1.25);
  CHECK_FALSE(q.multiplier);
}

TEST_CASE("bright job: a klein_gordon breather's multiplier through exp(2 pi i/3), located and checked" * doctest::test_suite("fast")) {
  // klein_gordon at C = 0.3 (band [1, sqrt(2.2)]), the site-centred breather continued up from
  // omega_b = 2.05 on 31 sites: between the first two points (2.05, 2.1345) a phonon multiplier of the
  // ring, exp(-i omega_q T_b) with omega_q near 2 omega_b/3, passes exp(+-2 pi i/3). Bisection on
  // re-solved breathers to 1e-6 located it at omega_b = 2.0510924 (measured; error bound 3.2e-7).
  using namespace lrchain::jobs::bright_breather;
  const Model kg = shipped_model("klein_gordon", {{"C", 0.3}});
  BrightBreatherConfig c = klein_gordon_branch(kg, 2.05, [](BrightBreatherConfig& x) { x.points = 2, x.ds = 0.2; });
  const BrightBreatherResult r = run(c);
  INFO(failure(r).value_or(""));
  REQUIRE(!failure(r));
  REQUIRE(r.bifurcations.size() == 1);
  const BranchBifurcation& b = r.bifurcations[0];
  CHECK(b.kind == "period_tripling");
  REQUIRE(b.located);
  CHECK(b.location_error <= 0.5e-6);
  CHECK(b.omega_b > b.omega_low);
  CHECK(b.omega_b < b.omega_high);
  CHECK(b.omega_b == doctest::Approx(2.0510924).epsilon(1e-6));
  // The multiplier's angle 2 pi omega_q / omega_b moves about 2 pi (2/3) / omega_b = 2 rad per unit
  // omega_b, so within the error bound it lies within ~1e-6 of exp(2 pi i/3) (measured 3.3e-7).
  REQUIRE(b.multiplier);
  CHECK(std::abs(*b.multiplier - std::polar(1.0, two_thirds_pi)) <= 2e-6);
  // Independent check: the floquet step (a fresh solve from the NLS seed, its own monodromy) just below
  // and above the located value counts a different number of multipliers past 2 pi/3.
  auto sector_count = [&](double omega_b) {
    BrightBreatherConfig f = c;
    f.step = BrightStep::floquet;
    f.omega_b = omega_b;
    validate(f);
    const BrightBreatherResult s = run(f);
    REQUIRE(!failure(s));
    return multipliers_beyond_two_thirds(*s.floquet);
  };
  CHECK(sector_count(b.omega_b - 2e-6) != sector_count(b.omega_b + 2e-6));
  // Without locating, the same crossing is only bracketed between the branch points.
  c.locate_tolerance = 0;
  const BrightBreatherResult bracketed = run(c);
  REQUIRE(bracketed.bifurcations.size() == 1);
  CHECK_FALSE(bracketed.bifurcations[0].located);
  CHECK(bracketed.bifurcations[0].omega_b == doctest::Approx(0.5 * (b.omega_low + b.omega_high)).epsilon(1e-14));
}

TEST_CASE("bright job: a Krein collision on a klein_gordon branch, located and checked two ways" * doctest::test_suite("fast")) {
  // klein_gordon at C = 1 (band [1, sqrt(5)]), the site-centred breather continued up from omega_b = 2.7
  // on 31 sites: stable at 2.8174, unstable (a complex quadruplet, |lambda| = 1.0015) at 2.8533. The
  // bisection locates the onset at omega_b = 2.8249066 (measured), the quadruplet's multiplier just past
  // it at angle 2.6013 with |lambda| - 1 = 2.6e-5.
  using namespace lrchain::jobs::bright_breather;
  const Model kg = shipped_model("klein_gordon", {{"C", 1.0}});
  const BrightBreatherConfig c = klein_gordon_branch(kg, 2.7, [](BrightBreatherConfig& x) { x.points = 4, x.ds = 0.2; });
  const BrightBreatherResult r = run(c);
  INFO(failure(r).value_or(""));
  REQUIRE(!failure(r));
  const BranchBifurcation& k = first_of_kind(r, "krein_collision");
  REQUIRE(k.located);
  REQUIRE(k.multiplier);
  CHECK(k.location_error <= 0.5e-6);
  CHECK(k.omega_b == doctest::Approx(2.8249066).epsilon(1e-6));
  CHECK(std::abs(*k.multiplier) > 1 + 1e-6);  // past the onset, off the circle,
  CHECK(std::abs(*k.multiplier) < 1 + 1e-4);  // by O(sqrt(location error))
  const double angle = std::arg(*k.multiplier);
  // The branch solved to a given omega_b (its last point there), without locating.
  auto last_point = [&](double to) {
    BrightBreatherConfig f = c;
    f.points = 20;
    f.to = to;
    f.locate_tolerance = 0;
    validate(f);
    BrightBreatherResult s = run(f);
    REQUIRE(!failure(s));
    REQUIRE(s.branch.points.back().omega_b == doctest::Approx(to).epsilon(1e-14));
    return s;
  };
  // Check 1 (Hamiltonian-Hopf law): past the collision |lambda| - 1 grows like sqrt(omega_b - omega*);
  // the straight line through (|lambda| - 1)^2 at omega* + 1e-5 and + 4e-5 extrapolates to zero at
  // omega* within 1e-7 (measured 5e-8; pairs of 1e-5, 2e-5, 4e-5 spread by 1.5e-7 with the curvature).
  const double w1 = k.omega_b + 1e-5, w2 = k.omega_b + 4e-5;
  const double extrapolated = hopf_onset(w1, last_point(w1).branch_floquets.back().max_nontrivial_modulus, w2,
                                         last_point(w2).branch_floquets.back().max_nontrivial_modulus);
  CHECK(std::abs(extrapolated - k.omega_b) <= k.location_error + 2e-7);
  // Check 2 (MacKay's criterion): just before the collision (omega* - 1e-4), two multipliers on the
  // circle within 3e-3 rad of the collision's angle carry opposite Krein signatures (measured: 2.6013
  // with -1, 2.6028 with +1).
  const BrightBreatherResult before = last_point(k.omega_b - 1e-4);
  CHECK(before.branch_floquets.back().stable);
  int plus = 0, minus = 0;
  for (const KreinMultiplier& m : before.branch_krein.back())
    if (std::abs(std::arg(m.lambda) - angle) < 3e-3) (m.signature > 0 ? plus : minus)++;
  CHECK(plus == 1);
  CHECK(minus == 1);
}

TEST_CASE("bright job: the site-centred klein_gordon breather loses stability in C, located and checked" * doctest::test_suite("fast")) {
  // klein_gordon at omega_b = 2.7, the site-centred breather continued in the coupling from C = 1 down
  // to 0.89 on 31 sites: stable at 1 and 0.9541, unstable at 0.9077 (|lambda| = 1.0011). The bisection in
  // C (each breather re-solved on the lattice at that C) locates the Krein collision at C* = 0.9082722
  // (measured), |lambda| - 1 = 2.9e-5 just past it.
  using namespace lrchain::jobs::bright_breather;
  const Model kg = shipped_model("klein_gordon", {{"C", 1.0}});
  const BrightBreatherConfig c = klein_gordon_branch(kg, 2.7, [](BrightBreatherConfig& x) {
    x.parameter = "C", x.to = 0.89, x.points = 30, x.ds = 0.05;
  });
  const BrightBreatherResult r = run(c);
  INFO(failure(r).value_or(""));
  REQUIRE(!failure(r));
  const BranchBifurcation* it = &first_of_kind(r, "krein_collision");
  REQUIRE(it->located);
  CHECK(it->location_error <= 0.5e-6);
  CHECK(it->omega_b == doctest::Approx(0.9082722).epsilon(1e-6));  // the record's value of the continued C
  REQUIRE(it->multiplier);
  CHECK(std::abs(*it->multiplier) > 1 + 1e-6);
  CHECK(std::abs(*it->multiplier) < 1 + 1e-4);
  // Independent check: the square-root law below C* (the unstable side), from the branch's last points
  // solved at C* - 1e-5 (|lambda| = 1.000157026) and C* - 4e-5 (1.000313131), not located: the line
  // through (|lambda| - 1)^2 meets zero 7.8e-8 from the located C*.
  auto modulus_at = [&](double to) {
    BrightBreatherConfig f = c;
    f.to = to;
    f.locate_tolerance = 0;
    validate(f);
    const BrightBreatherResult s = run(f);
    REQUIRE(!failure(s));
    REQUIRE(s.branch.points.back().parameter == doctest::Approx(to).epsilon(1e-14));
    return s.branch_floquets.back().max_nontrivial_modulus;
  };
  const double c1 = it->omega_b - 1e-5, c2 = it->omega_b - 4e-5;
  CHECK(std::abs(hopf_onset(c1, modulus_at(c1), c2, modulus_at(c2)) - it->omega_b) <= it->location_error + 2e-7);
}
