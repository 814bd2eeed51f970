// The regime jobs (lrchain/jobs/regime_job.hpp) called directly: the paper chain's intervals and
// maps, a model file's map checked pixel by pixel against lrchain::coefficients (an independent
// evaluation of sign(omega'' h_tilde)), the Config keys in errors, and the files of a map.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "lrchain/coefficients.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/regime/regime_map.hpp"
#include "lrchain/jobs/output_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain;
using namespace lrchain::jobs;

namespace {

// The Config key an InvalidParameter from `job` names ("" if none is thrown).
template <class Job>
std::string key_of(Job&& job) {
  try {
    job();
  } catch (const InvalidParameter& e) {
    return e.parameter();
  }
  return "";
}

// Pixel value of regime_map.hpp from an independent evaluation of the coefficients.
int expected_pixel(const NlsCoefficients& c) {
  if (c.regime == Regime::singular) return regime::PixelRegime::singular;
  return c.regime == Regime::focusing ? regime::PixelRegime::focusing : regime::PixelRegime::defocusing;
}

}  // namespace

TEST_CASE("regime job intervals: the paper chain's optical branch at rho = 1/3 focuses up to omega'' = 0") {
  RegimeIntervalsConfig c;
  c.lattice.params = Params{};  // alpha 3/2, delta0 4/9, kappa 1, rho 1/3 (Sec. 4)
  const RegimeIntervalsResult r = run(c);
  CHECK(r.branch == "optical");
  REQUIRE(!r.structure.intervals.empty());
  // Sec. 3.3 / Fig. 2: omega'' = 0 at theta ~ 1.8916 ends the first focusing interval.
  CHECK(r.structure.intervals[0].hi == doctest::Approx(1.8916).epsilon(1e-4));
  CHECK(r.structure.intervals[0].hi_cause == regime::BoundaryCause::curvature_zero);
  CHECK(to_json(r)["theta_tolerance"] == 1e-12);

  // The same chain as a loaded model goes through the generic evaluators: the same ends to 2e-12.
  RegimeIntervalsConfig m = c;
  m.lattice.model = std::make_shared<const Model>(resonant_chain_model(Params{}));
  const RegimeIntervalsResult g = run(m);
  REQUIRE(g.structure.intervals.size() == r.structure.intervals.size());
  for (std::size_t k = 0; k < g.structure.intervals.size(); ++k) {
    CHECK(std::abs(g.structure.intervals[k].lo - r.structure.intervals[k].lo) <= 2e-12);
    CHECK(std::abs(g.structure.intervals[k].hi - r.structure.intervals[k].hi) <= 2e-12);
  }
}

TEST_CASE("regime job map of a model file: every pixel is the sign of curvature * h_tilde") {
  RegimeMapConfig c;
  c.lattice.model = std::make_shared<const Model>(shipped_model("klein_gordon", {{"C", 0.5}}));
  c.axis = "b";
  c.axis_range = Range{0.5, 2.0};
  c.nx = 9;
  c.ny = 11;
  c.curves = false;
  const RegimeMapResult r = run(c);
  CHECK(r.plane == "theta-b");
  REQUIRE(r.panels.size() == 1);  // the model's only branch
  const RegimeMapPanel& p = r.panels[0];
  int checked = 0;
  for (Index i = 0; i < p.x.n; ++i) {
    const Model at = shipped_model("klein_gordon", {{"C", 0.5}, {"b", p.x.at(i)}});
    for (Index j = 0; j < p.y.n; ++j) {
      const NlsCoefficients k = coefficients(at, 0, p.y.at(j));
      if (k.regime != Regime::singular && std::abs(k.curvature * k.h_tilde) < 1e-9) continue;  // on a boundary
      INFO("b " << p.x.at(i) << ", theta " << p.y.at(j));
      CHECK(int(p.values[std::size_t(j * p.x.n + i)]) == expected_pixel(k));
      ++checked;
    }
  }
  CHECK(checked > 80);
}

TEST_CASE("regime job map of the paper chain: theta-rho pixels and the CLI's default rho ranges") {
  CHECK(default_rho_range(Branch::optical) == Range{0.01, 30.0});
  CHECK(default_rho_range(Branch::acoustic) == Range{0.01, 2.5});
  RegimeMapConfig c;
  c.branch = "acoustic";
  c.nx = 7;
  c.ny = 8;
  c.curves = c.inset = false;
  const RegimeMapResult r = run(c);
  REQUIRE(r.panels.size() == 1);
  const RegimeMapPanel& p = r.panels[0];
  CHECK(p.x.lo == 0.01);
  CHECK(p.x.hi == 2.5);
  for (Index i = 0; i < p.x.n; ++i)
    for (Index j = 0; j < p.y.n; ++j) {
      Params q;
      q.rho = p.x.at(i);
      const NlsCoefficients k = coefficients(q, Branch::acoustic, p.y.at(j));
      if (k.regime != Regime::singular && std::abs(k.curvature * k.h_tilde) < 1e-9) continue;
      CHECK(int(p.values[std::size_t(j * p.x.n + i)]) == expected_pixel(k));
    }
}

TEST_CASE("regime jobs name their Config keys in errors") {
  RegimeMapConfig c;
  c.rho_range = Range{5, 1};
  CHECK(key_of([&] { validate(c); }) == "rho_range");
  c = {};
  c.plane = "delta0-omega";
  c.omega_range = Range{0, 99};
  CHECK(key_of([&] { validate(c); }) == "omega_range");
  c = {};
  c.lattice.model = std::make_shared<const Model>(shipped_model("fput"));
  c.rho_range = Range{0.1, 1};
  CHECK(key_of([&] { validate(c); }) == "axis_range");
  c.rho_range.reset();
  c.axis = "b";  // fput's b has no declared range: axis_range is required
  CHECK(key_of([&] { validate(c); }) == "axis_range");
  RegimeIntervalsConfig i;
  i.samples = 3;
  CHECK(key_of([&] { validate(i); }) == "samples");
  RegimeThresholdsConfig t;
  t.scan = 5;
  CHECK(key_of([&] { validate(t); }) == "scan");
}

TEST_CASE("regime job map write: the CSV pixel map, the boundary polylines and the gnuplot script") {
  const fs::path dir = fs::temp_directory_path() / ("lrchain-regime-job-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  RegimeMapConfig c;
  c.branch = "optical";
  c.nx = 5;
  c.ny = 4;
  c.figures = false;
  const RegimeMapResult r = run(c);
  jobs::Figures figures(dir);
  const RegimeMapFiles files = write(r, dir, figures);
  REQUIRE(files.files.size() == 1);
  CHECK(files.files[0].front() == "regime_theta-rho_optical.csv");
  CHECK(files.files[0].back() == "regime_theta-rho.gp");
  for (const auto& f : files.files[0]) CHECK(fs::is_regular_file(dir / f));
  std::ifstream csv(dir / "regime_theta-rho_optical.csv");
  std::string header;
  std::getline(csv, header);
  CHECK(header == "rho,theta,regime");
  const auto j = to_json(r, files);
  CHECK(j["panels"][0]["rho_range"] == nlohmann::json({0.01, 30.0}));
  CHECK(!j.contains("png"));
  fs::remove_all(dir);
}
