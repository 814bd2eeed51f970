// Paper-number tests of the focusing/defocusing regimes (Sec. 3.3 focdef, Sec. 4.3 mblm,
// Sec. 5.1 dedb): focusing theta-intervals, their causes, the special mass ratios and
// precompressions, maps and boundary curves. Tolerances follow the paper's printed rounding.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "../support/run_lrchain.hpp"
#include "lrchain/coefficients.hpp"
#include "lrchain/regime/boundary_curves.hpp"
#include "lrchain/regime/focusing_intervals.hpp"
#include "lrchain/regime/frequency_band.hpp"
#include "lrchain/regime/paper_thresholds.hpp"
#include "lrchain/regime/regime_events.hpp"
#include "lrchain/regime/regime_map.hpp"

using namespace lrchain;
using namespace lrchain::regime;
constexpr double pi = std::numbers::pi;

namespace {
Params paper_with_rho(double rho) {
  Params p;
  p.rho = rho;
  return p;
}
// The reported end is within 1e-12 of a sign change of the smooth function of its cause.
void check_end_is_zero(const Params& p, Branch b, double theta, BoundaryCause cause) {
  if (cause == BoundaryCause::band_edge) return;
  const auto f = regime_functions(p, b);
  const double lo = f(theta - 1e-12)[cause], hi = f(theta + 1e-12)[cause];
  CHECK_MESSAGE(lo * hi <= 0.0, "cause ", to_string(cause), " at theta ", theta);
}
}  // namespace

TEST_CASE("rho = 1/3 optical: one focusing interval (0, theta_c), theta_c ~ 1.892 (Sec. 3.3)") {
  const auto iv = focusing_intervals(paper_with_rho(1.0 / 3.0), Branch::optical);
  REQUIRE(iv.size() == 1);
  CHECK(iv[0].lo == 0.0);
  CHECK(iv[0].lo_cause == BoundaryCause::band_edge);
  CHECK(std::abs(iv[0].hi - 1.892) <= 5e-4);
  CHECK(iv[0].hi_cause == BoundaryCause::curvature_zero);
  check_end_is_zero(paper_with_rho(1.0 / 3.0), Branch::optical, iv[0].hi, iv[0].hi_cause);
}

TEST_CASE("rho = 10 optical: (0, 0.3681) and (1.2263, 2.4389) (Sec. 4.3, mblm)") {
  const Params p = paper_with_rho(10.0);
  const auto iv = focusing_intervals(p, Branch::optical);
  REQUIRE(iv.size() == 2);
  CHECK(iv[0].lo == 0.0);
  CHECK(std::abs(iv[0].hi - 0.3681) <= 5e-5);
  CHECK(std::abs(iv[1].lo - 1.2263) <= 5e-5);
  CHECK(std::abs(iv[1].hi - 2.4389) <= 5e-5);
  // Sec. 4.3: the ends 0.3681 and 2.4389 are poles of h_tilde with c^2(1+rho) - K2 ~ 0;
  // near 1.2263 omega'' ~ 0.
  CHECK(iv[0].hi_cause == BoundaryCause::nonresonance2);
  CHECK(iv[1].lo_cause == BoundaryCause::curvature_zero);
  CHECK(iv[1].hi_cause == BoundaryCause::nonresonance2);
  for (const auto& i : iv) {
    check_end_is_zero(p, Branch::optical, i.lo, i.lo_cause);
    check_end_is_zero(p, Branch::optical, i.hi, i.hi_cause);
  }
}

TEST_CASE("rho = 1/3 acoustic: focusing on (1.784, 1.949) between a pole and h_tilde = 0") {
  const Params p = paper_with_rho(1.0 / 3.0);
  const auto iv = focusing_intervals(p, Branch::acoustic);
  REQUIRE(iv.size() == 1);
  CHECK(std::abs(iv[0].lo - 1.7841) <= 5e-5);  // issue 3 quotes 1.7841, the paper 1.784
  // Paper prints 1.949; h_tilde = 0 is at 1.950015 both here and in an independent 30-digit
  // evaluation of the paper's own formulas (docs/paper-errata.md, regime section).
  CHECK(std::abs(iv[0].hi - 1.95001489350291) <= 1e-9);
  CHECK(std::abs(iv[0].hi - 1.949) <= 1.5e-3);
  // Sec. 3.3: on the acoustic branch eq:nonresonance2 always holds; the pole is eq:nonresonance1.
  CHECK(iv[0].lo_cause == BoundaryCause::nonresonance1);
  CHECK(iv[0].hi_cause == BoundaryCause::h_tilde_zero);
  check_end_is_zero(p, Branch::acoustic, iv[0].lo, iv[0].lo_cause);
  check_end_is_zero(p, Branch::acoustic, iv[0].hi, iv[0].hi_cause);
}

TEST_CASE("rho = 0.32, delta0 = 0.27 acoustic: focusing on (1.888, 2.003) (Sec. 5.1, dedb)") {
  const Params p{1.5, 0.27, 1.0, 0.32};
  const auto iv = focusing_intervals(p, Branch::acoustic);
  REQUIRE(iv.size() == 1);
  // Paper prints 1.888 (truncated; the pole is at 1.88884, docs/paper-errata.md) and 2.003;
  // 2.00343809383857 is the 30-digit zero of the paper's h_tilde formula.
  CHECK(std::abs(iv[0].lo - 1.888) <= 1e-3);
  CHECK(std::abs(iv[0].hi - 2.003) <= 5e-4);
  CHECK(std::abs(iv[0].hi - 2.00343809383857) <= 1e-9);
}

TEST_CASE("acoustic branch: omega'' < 0 and eq:nonresonance2 never violated (Sec. 3.3)") {
  for (double rho : {0.05, 0.32, 1.0, 3.0, 20.0}) {
    const auto s = regime_structure(regime_functions(paper_with_rho(rho), Branch::acoustic));
    for (const auto& r : s.roots) {
      CHECK(r.cause != BoundaryCause::curvature_zero);
      CHECK(r.cause != BoundaryCause::nonresonance2);
    }
  }
}

TEST_CASE("special mass ratios and precompressions as codimension-two points (Sec. 3.3)") {
  for (const auto& s : paper_threshold_scenarios()) {
    const auto events = regime_events(s.base, s.branch, s.axis, s.scan);
    const auto matched = match_paper_values(s, events);
    for (const auto& m : matched) {
      INFO(s.name, ": paper ", m.paper, " computed ", m.event.value);
      REQUIRE(m.found);
      // three printed decimals for the rho values; "about" values: 10 % for delta0 0.22 and
      // 0.06, within a factor 1.5 for "about 0.002"
      const double rel = std::abs(m.event.value / m.paper - 1.0);
      // rho values printed with three decimals. 15.335: the fold of h_tilde = 0 is at 15.33446
      // (also from the paper's formulas at 30 digits), i.e. 15.334 -- docs/paper-errata.md.
      if (s.axis == ParameterAxis::rho)
        CHECK(std::abs(m.event.value - m.paper) <= (m.paper == 15.335 ? 6e-4 : 5e-4 + 1e-12));
      else if (m.paper < 0.01)
        CHECK(rel <= 0.5);
      else
        CHECK(rel <= 0.1);
    }
  }
}

TEST_CASE("rho = 17.8 optical: focusing bands 1 -> 2 -> 3 -> 4 -> 3 as delta0 grows (Fig. 4)") {
  const auto s = paper_threshold_scenarios()[3];
  REQUIRE(s.name == "optical_delta0_rho17.8");
  const auto events = regime_events(s.base, s.branch, s.axis, s.scan);
  std::vector<int> counts{static_cast<int>(
      focusing_intervals(with_parameter(s.base, s.axis, s.scan.lo), s.branch).size())};
  for (const auto& e : events)
    if (e.intervals_after != counts.back()) counts.push_back(e.intervals_after);
  CHECK(counts == std::vector<int>{1, 2, 3, 4, 3});
}

TEST_CASE("theta-rho map agrees with the root-found intervals away from their ends") {
  const GridAxis rho{0.5, 25.0, 40}, theta{pi / 200, pi, 200};
  for (Branch b : {Branch::optical, Branch::acoustic}) {
    const RegimeMap m = theta_rho_map(Params{}, b, rho, theta);
    int mismatches = 0;
    for (int i = 0; i < rho.n; ++i) {
      const auto iv = focusing_intervals(paper_with_rho(rho.at(i)), b);
      for (int j = 0; j < theta.n; ++j) {
        const double th = theta.at(j);
        bool inside = false, near_end = false;
        for (const auto& f : iv) {
          inside |= th > f.lo && th < f.hi;
          near_end |= std::abs(th - f.lo) < 1e-9 || std::abs(th - f.hi) < 1e-9;
        }
        if (near_end) continue;
        mismatches += inside != (m.at(i, j) == PixelRegime::focusing);
      }
    }
    CHECK(mismatches == 0);
  }
}

TEST_CASE("boundary curves lie on the zero sets: each point is a root in theta at its rho") {
  const auto curves = boundary_curves(Params{}, Branch::optical, ParameterAxis::rho, 0.5, 30.0);
  int checked = 0;
  for (const auto& c : curves) {
    for (std::size_t k = 0; k < c.points.size(); k += 25) {
      const auto& pt = c.points[k];
      if (pt.x <= 0.5 || pt.x >= 30.0 || pt.y <= 1e-3 || pt.y >= pi) continue;
      const auto f = regime_functions(paper_with_rho(pt.x), Branch::optical);
      // distance to the zero set below 1e-9 in theta or rho: a sign change in a small box.
      const double d = 1e-9;
      const double a = f(pt.y - d)[c.cause], b = f(pt.y + d)[c.cause];
      const auto g = regime_functions(paper_with_rho(pt.x + d), Branch::optical);
      const auto h = regime_functions(paper_with_rho(pt.x - d), Branch::optical);
      const bool crosses = a * b <= 0.0 || g(pt.y)[c.cause] * h(pt.y)[c.cause] <= 0.0;
      CHECK_MESSAGE(crosses, to_string(c.cause), " at rho ", pt.x, " theta ", pt.y);
      ++checked;
    }
  }
  CHECK(checked > 20);
  // Fig. 2 legend: the optical boundaries include omega''=0, eq:nonresonance2 and h_tilde=0.
  int n_curv = 0, n_nr2 = 0, n_num = 0;
  for (const auto& c : curves) {
    n_curv += c.cause == BoundaryCause::curvature_zero;
    n_nr2 += c.cause == BoundaryCause::nonresonance2;
    n_num += c.cause == BoundaryCause::h_tilde_zero;
  }
  CHECK(n_curv >= 1);
  CHECK(n_nr2 >= 1);
  CHECK(n_num >= 1);
}

TEST_CASE("CLI: regime intervals prints the JSON intervals — bad input exits 2") {
  const auto run = lrchain::test::run_lrchain({"regime", "intervals", "--rho", "10", "--branch", "optical", "--json"});
  CHECK(run.exit_code == 0);
  const auto j = nlohmann::json::parse(run.out);
  REQUIRE(j["intervals"].size() == 2);
  CHECK(std::abs(j["intervals"][1]["hi"].get<double>() - 2.4389) <= 5e-5);
  CHECK(j["intervals"][1]["hi_cause"] == "nonresonance2");
  CHECK(lrchain::test::run_lrchain({"regime", "intervals", "--rho", "-1"}).exit_code == 2);
}
