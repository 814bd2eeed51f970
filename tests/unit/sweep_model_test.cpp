// Sweeps whose base is a model-file simulate config (`model = "models/fput.toml"`): any model
// parameter ("parameters.b") and any number key of the job ("bright.theta") is an axis, the model
// is loaded once per sweep, and each point equals the single run of `lrchain simulate --config`
// with that point's values, bit for bit (the same job function, jobs::simulate_model_bright, on the
// same doubles: the run is deterministic). Bad input (an unknown parameter axis, a missing model
// file) exits 2 with one line naming the file and writes nothing.
#include <doctest/doctest.h>

#include <boost/math/tools/roots.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/jobs/model_experiment_config.hpp"
#include "lrchain/jobs/dark_job.hpp"
#include "lrchain/jobs/model_source.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/jobs/simulate/model_simulate_job.hpp"
#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"
#include "lrchain/process.hpp"
#include "../support/run_lrchain.hpp"
#include "sweep_test_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain::jobs::sweep;

namespace {

fs::path scratch(const std::string& name) { return lrchain::test::sweep_scratch("sweep-model-test", name); }

const std::string fput_file = std::string(LRCHAIN_SOURCE_DIR) + "/models/fput.toml";

// examples/models/fput_bright.toml shortened: 401 sites, 10 T_b, detuning 1e-3 (inverse width
// 0.075: about 13 sites, where 1e-4 would not fit on 401); `b` is the cubic coefficient.
std::string fput_bright_base(const std::string& b, const std::string& model = fput_file) {
  return "experiment = \"bright\"\nmodel = \"" + model + "\"\n[parameters]\na = \"1/4\"\nb = \"" + b +
         "\"\n[bright]\nbranch = \"acoustic\"\ntheta = \"pi/2\"\ndetuning = 1e-3\nsites = 401\nn0 = -100\nperiods = 10\n";
}

// A sweep file of `job` over `parameter` = [`values`] whose base is base.toml next to it.
std::string sweep_file(const std::string& job, const std::string& parameter, const std::string& values, const fs::path& output) {
  return "job = \"" + job + "\"\nbase = \"base.toml\"\noutput = \"" + output.string() + "\"\n[[axis]]\nparameter = \"" +
         parameter + "\"\nvalues = [" + values + "]\n";
}

std::string sweep_over(const std::string& parameter, const std::string& values, const fs::path& output) {
  return sweep_file("bright", parameter, values, output);
}

// Writes `base` and a sweep of `job` over `parameter` (results in d/r.h5) into `d`, and loads the
// sweep as `lrchain sweep` loads it.
SweepConfig write_sweep(const fs::path& d, const std::string& job, const std::string& base, const std::string& parameter,
                        const std::string& values) {
  lrchain::test::write_text(d / "base.toml", base);
  lrchain::test::write_text(d / "s.toml", sweep_file(job, parameter, values, d / "r.h5"));
  return load_sweep_config(d / "s.toml");
}

// A sweep over `parameter` (`values`, results in d/r.h5) of the fput base with cubic coefficient
// `b`, both written into `d`, loaded as `lrchain sweep` loads it.
SweepConfig fput_sweep(const fs::path& d, const std::string& b, const std::string& parameter, const std::string& values) {
  return write_sweep(d, "bright", fput_bright_base(b), parameter, values);
}

// Runs the sweep on 2 threads, quietly, and reads its results file back.
SweepResults run_on_two_threads(const SweepConfig& c, const Job& job) {
  SweepRunOptions o;
  o.threads = 2;
  o.progress = false;
  run_sweep(c, job, o);
  return read_results(c.output, c, job);
}

// The JSON summary `lrchain simulate --config` prints for the model config `text`, computed through
// the job function it calls (cli/src/simulate_model_bright.cpp), without files.
nlohmann::json single_run(const std::string& text) {
  const auto mc = lrchain::jobs::load_model_experiment_config(lrchain::config::Document::from_text(text, "single.toml"));
  const lrchain::Model model = lrchain::shipped_model("fput", mc.parameters);
  auto c = mc.bright;
  lrchain::jobs::prepare(model, c, mc.branch);
  const lrchain::jobs::ModelSource source(fput_file, "model", nullptr);
  return lrchain::jobs::simulate_model_bright(model, *source.lattice().kernels, c, {}, {"", false, "csv"}).summary;
}

double scalar(const SweepResults& r, const std::string& name, std::size_t point) {
  const auto it = std::find(r.scalar_names.begin(), r.scalar_names.end(), name);
  REQUIRE(it != r.scalar_names.end());
  return r.scalars[std::size_t(it - r.scalar_names.begin()) * r.points + point];
}

// The sweep's scalars of `point` equal the single run's JSON summary bit for bit.
void check_equals_single_run(const SweepResults& r, std::size_t point, const nlohmann::json& j) {
  CAPTURE(point);
  CHECK(scalar(r, "max_E_x", point) == j["max_E_x"].get<double>());
  CHECK(scalar(r, "final_E_x", point) == j["final_E"][0].get<double>());
  CHECK(scalar(r, "centre_speed", point) == j["centre_speed"].get<double>());
  CHECK(scalar(r, "centre_speed_vs_c", point) == j["centre_speed_vs_c"].get<double>());
  CHECK(scalar(r, "max_relative_energy_drift", point) == j["max_relative_energy_drift"].get<double>());
  CHECK(scalar(r, "omega_b", point) == j["ansatz"]["omega_b"].get<double>());
  CHECK(scalar(r, "T_b", point) == j["ansatz"]["T_b"].get<double>());
  CHECK(scalar(r, "h_tilde", point) == j["ansatz"]["h_tilde"].get<double>());
  CHECK(scalar(r, "t_end", point) == j["t_end"].get<double>());
  CHECK(scalar(r, "steps", point) == j["steps"].get<double>());
}

}  // namespace

TEST_CASE("sweep of a model file: a parameters.b axis on 2 threads gives each point's single simulate run bit for bit") {
  const fs::path d = scratch("b-axis");
  const SweepConfig c = fput_sweep(d, "1/2", "parameters.b", "0.5, 0.75");
  const Job job = make_job(c);
  REQUIRE(job.model_source() != nullptr);
  CHECK(job.model_source() == c.base_job->model_source());  // loaded once: the sweep's job shares it
  CHECK(job.has_parameter("parameters.a"));
  CHECK(job.has_parameter("parameters.b"));
  CHECK(job.has_parameter("bright.theta"));
  const SweepResults r = run_on_two_threads(c, job);
  REQUIRE(r.points == 2);
  CHECK(r.failed() == 0);
  CHECK(r.finished() == 2);
  check_equals_single_run(r, 0, single_run(fput_bright_base("0.5")));
  check_equals_single_run(r, 1, single_run(fput_bright_base("0.75")));
  // b changes the nonlinearity: h_tilde of the acoustic branch at pi/2 differs between the points,
  // and the breather stays within a percent of its ansatz over 10 T_b at both (0.15 % measured at b = 1/2).
  CHECK(scalar(r, "h_tilde", 0) != scalar(r, "h_tilde", 1));
  CHECK(scalar(r, "max_E_x", 0) < 1e-2);
  CHECK(scalar(r, "max_E_x", 1) < 1e-2);
  fs::remove_all(d);
}

TEST_CASE("sweep of a model file: a bright.theta axis point equals the single run with that theta") {
  const fs::path d = scratch("theta-axis");
  const SweepConfig c = fput_sweep(d, "1/2", "bright.theta", "1.2");
  const JobResult point = make_job(c).run(c.overrides(0));
  REQUIRE(point.status == PointStatus::ok);
  SweepResults r(make_job(c), 1);
  r.set(0, point);
  std::string single = fput_bright_base("1/2");
  single.replace(single.find("\"pi/2\""), 6, "1.2");
  check_equals_single_run(r, 0, single_run(single));
  fs::remove_all(d);
}

TEST_CASE("sweep of a model file: a results file does not resume once the model file's bytes changed") {
  const fs::path d = scratch("model-changed");
  fs::copy_file(fput_file, d / "model.toml");
  lrchain::test::write_text(d / "base.toml", fput_bright_base("1/2", (d / "model.toml").string()));
  lrchain::test::write_text(d / "s.toml", sweep_over("parameters.b", "0.5", d / "r.h5"));
  const SweepConfig first = load_sweep_config(d / "s.toml");
  SweepOutcome outcome = run_sweep(first, make_job(first), SweepRunOptions{.threads = 1, .progress = false, .on_progress = {}});
  CHECK(outcome.finished == 1);
  CHECK_NOTHROW(read_results(first.output, first, make_job(first)));
  // The same name now holds klein_gordon's bytes (parameters a and b too): the sweep's identity differs.
  fs::copy_file(fs::path(LRCHAIN_SOURCE_DIR) / "models" / "klein_gordon.toml", d / "model.toml", fs::copy_options::overwrite_existing);
  const SweepConfig second = load_sweep_config(d / "s.toml");
  CHECK_THROWS_WITH_AS(read_results(second.output, second, make_job(second)),
                       doctest::Contains("its model file changed since the file was written"), lrchain::InputError);
  fs::remove_all(d);
}

TEST_CASE("sweep of a model file: a value out of the model's range is an invalid point, the others run") {
  const fs::path d = scratch("range");
  const SweepConfig c = fput_sweep(d, "1/2", "bright.theta", "4, 1.5");
  const Job job = make_job(c);
  const JobResult bad = job.run(c.overrides(0)), good = job.run(c.overrides(1));
  CHECK(bad.status == PointStatus::invalid);
  CHECK(bad.reason.find("theta") != std::string::npos);
  CHECK(std::isnan(bad.scalars.at(0)));
  CHECK(good.status == PointStatus::ok);
  fs::remove_all(d);
}

TEST_CASE("sweep of a model file: the CLI's results equal lrchain simulate --config of the point") {
  const fs::path d = scratch("cli");
  lrchain::test::write_text(d / "base.toml", fput_bright_base("1/2"));
  lrchain::test::write_text(d / "s.toml", sweep_over("parameters.b", "0.75", d / "r.h5"));
  const auto sweep = lrchain::test::run_lrchain({"sweep", "--config", (d / "s.toml").string(), "--quiet", "--threads", "1"});
  REQUIRE_MESSAGE(sweep.exit_code == 0, sweep.err);
  CHECK(nlohmann::json::parse(sweep.out)["finished"] == 1);
  CHECK(fs::exists(d / "r.h5"));
  CHECK(fs::exists(d / "r.csv"));
  lrchain::test::write_text(d / "point.toml", fput_bright_base("0.75"));
  const auto single = lrchain::test::run_lrchain(
      {"simulate", "--config", (d / "point.toml").string(), "--out", (d / "single").string(), "--no-figures"});
  REQUIRE_MESSAGE(single.exit_code == 0, single.err);
  const SweepConfig c = load_sweep_config(d / "s.toml");
  check_equals_single_run(read_results(c.output, c, make_job(c)), 0, nlohmann::json::parse(single.out));
  fs::remove_all(d);
}

TEST_CASE("sweep of a model file: an unknown parameter axis or a missing model file exits 2 with one line, writing nothing") {
  const fs::path d = scratch("bad");
  struct Case {
    std::string base, parameter, expected, file;
  };
  const Case cases[] = {
      {fput_bright_base("1/2"), "parameters.c", "did you mean 'parameters.", "s.toml"},
      {fput_bright_base("1/2"), "model.rho", "is not a number parameter of a \"bright\" job", "s.toml"},
      {fput_bright_base("1/2", (d / "no_such_model.toml").string()), "parameters.b", "'model'", "base.toml"},
      {fput_bright_base("1/2") + "c = 1\n", "bright.theta", "'c'", "base.toml"},  // not a key of [bright]
  };
  for (const auto& k : cases) {
    CAPTURE(k.base);
    CAPTURE(k.parameter);
    lrchain::test::write_text(d / "base.toml", k.base);
    lrchain::test::write_text(d / "s.toml", sweep_over(k.parameter, "0.5", d / "out" / "r.h5"));
    const auto r = lrchain::test::run_lrchain({"sweep", "--config", (d / "s.toml").string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(k.expected) != std::string::npos);
    CHECK(r.err.find(k.file) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(d / "out"));
  }
  // An unknown name in the base's [parameters]: at its line of the base config.
  std::string unknown = fput_bright_base("1/2");
  unknown.insert(unknown.find("[bright]"), "w0 = 2\n");
  lrchain::test::write_text(d / "base.toml", unknown);
  const auto r = lrchain::test::run_lrchain({"sweep", "--config", (d / "s.toml").string()});
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("base.toml:6") != std::string::npos);
  CHECK(r.err.find("w0") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK(!fs::exists(d / "out"));
  fs::remove_all(d);
}

namespace {

// A ring base (examples/models/*_ring.toml's shape): plane waves of amplitude U = `amplitude` at
// theta = pi/2 on the model's first branch, coupling C; `parameters` adds lines to [parameters].
std::string ring_base(const std::string& model, const std::string& parameters, const std::string& amplitude,
                      const std::string& C = "\"1/2\"") {
  return "experiment = \"ring\"\nmodel = \"" + model + "\"\n[parameters]\nC = " + C + "\n" + parameters +
         "[ring]\nbranch = \"branch0\"\ntheta = \"pi/2\"\namplitudes = [" + amplitude + "]\n";
}

// The rows of a sweep's CSV view, each as column -> text (row 0: the header's own names).
std::vector<std::map<std::string, std::string>> csv_rows(const fs::path& file) {
  std::ifstream in(file);
  std::vector<std::vector<std::string>> cells;
  for (std::string line; std::getline(in, line);) {
    cells.emplace_back();
    std::istringstream fields(line);
    for (std::string cell; std::getline(fields, cell, ',');) cells.back().push_back(cell);
    if (!line.empty() && line.back() == ',') cells.back().emplace_back();
  }
  std::vector<std::map<std::string, std::string>> rows;
  for (const auto& row : cells) {
    rows.emplace_back();
    for (std::size_t i = 0; i < row.size() && i < cells.at(0).size(); ++i) rows.back()[cells[0][i]] = row[i];
  }
  return rows;
}

std::string ring_sweep(const std::string& parameter, const std::string& values, const fs::path& output) {
  return sweep_file("ring", parameter, values, output);
}

}  // namespace

TEST_CASE("sweep of a model file: a ring point whose plane wave broke up is a numerical_failure point with the run's reason") {
  // Klein-Gordon with a = 0, b = -1/6 is sine-Gordon's cubic truncation: at U = 1 the plane wave is
  // modulationally unstable (h omega'' > 0) and breaks up (`lrchain simulate ring` exits 3); at
  // b = -1/50 the same amplitude stays a plane wave.
  const fs::path d = scratch("ring");
  lrchain::test::write_text(d / "base.toml", ring_base(std::string(LRCHAIN_SOURCE_DIR) + "/models/klein_gordon.toml",
                                                       "a = 0\nb = \"-1/6\"\n", "1"));
  lrchain::test::write_text(d / "s.toml", ring_sweep("parameters.b", "-0.1666666666666667, -0.02", d / "r.h5"));
  const SweepConfig c = load_sweep_config(d / "s.toml");
  const Job job = make_job(c);
  REQUIRE(job.model_source() != nullptr);
  const JobResult broke = job.run(c.overrides(0)), kept = job.run(c.overrides(1));
  SweepResults r(job, 2);
  r.set(0, broke);
  r.set(1, kept);
  CHECK(broke.status == PointStatus::numerical_failure);
  CHECK(broke.reason.find("amplitude 1: not measurable: the plane wave broke up at t = ") == 0);
  CHECK(broke.reason.find("modulational instability") != std::string::npos);
  // Its prediction stays (omega + h U^2/4 from the evaluators), its unmeasurable frequency is NaN.
  CHECK(std::isnan(scalar(r, "measured_frequency", 0)));
  CHECK(std::isnan(scalar(r, "relative_disagreement", 0)));
  CHECK(scalar(r, "predicted_frequency", 0) == doctest::Approx(scalar(r, "omega", 0) + scalar(r, "h", 0) / 4).epsilon(1e-15));
  // omega(pi/2)^2 = w0^2 + 4 C sin^2(pi/4) = 2 (the KG dispersion relation), whatever b.
  CHECK(scalar(r, "omega", 0) == doctest::Approx(std::sqrt(2.0)).epsilon(1e-14));
  CHECK(kept.status == PointStatus::ok);
  // b = -1/50: the measured shift agrees with h U^2/4 to 0.5 % (measured 0.47 %; O(U^2) of the NLS).
  CHECK(scalar(r, "relative_disagreement", 1) < 5e-3);
  // ... and equals the single run with b = -0.02 bit for bit (the same job function).
  const auto mc = lrchain::jobs::load_model_experiment_config(lrchain::config::Document::from_text(
      ring_base(std::string(LRCHAIN_SOURCE_DIR) + "/models/klein_gordon.toml", "a = 0\nb = -0.02\n", "1"), "single.toml"));
  const lrchain::jobs::ModelSource source(mc.model_file, "model", nullptr);
  const lrchain::Model model = source.model(mc.parameters);
  auto ring = mc.ring;
  lrchain::jobs::prepare(model, ring, mc.branch);
  const auto single = lrchain::jobs::simulate_ring(model, *source.lattice().kernels, ring, {}, {"", false, "csv"}).summary;
  CHECK(scalar(r, "measured_frequency", 1) == single["amplitudes"][0]["measured_frequency"].get<double>());
  CHECK(scalar(r, "relative_disagreement", 1) == single["amplitudes"][0]["relative_disagreement"].get<double>());
  CHECK(scalar(r, "packet_speed", 1) == single["packet"]["measured_speed"].get<double>());
  fs::remove_all(d);
}

TEST_CASE("sweep of a model file: a user's file is compiled once into the cache and its points equal lrchain simulate --config" *
          doctest::timeout(300)) {
  // tests/data/sine_gordon_poly.toml (not shipped: compiled at run time). At C = 1/2 the U = 1 plane
  // wave breaks up (simulate exits 3, the sweep point is numerical_failure); at C = 2 it is measured.
  const fs::path d = scratch("user-file");
  fs::copy_file(fs::path(LRCHAIN_SOURCE_DIR) / "tests" / "data" / "sine_gordon_poly.toml", d / "sine_gordon_poly.toml");
  const std::string model = (d / "sine_gordon_poly.toml").string();
  const std::vector<std::string> cache{"XDG_CACHE_HOME=" + (d / "cache").string()};
  lrchain::test::write_text(d / "base.toml", ring_base(model, "", "1"));
  lrchain::test::write_text(d / "s.toml", ring_sweep("parameters.C", "0.5, 2", d / "r.h5"));
  const auto sweep = lrchain::test::run_lrchain({"sweep", "--config", (d / "s.toml").string(), "--quiet", "--threads", "2"}, {}, cache);
  REQUIRE_MESSAGE(sweep.exit_code == 0, sweep.err);
  CHECK(nlohmann::json::parse(sweep.out)["failed"] == 1);
  // One object (evaluators and lattice kernels): the file was compiled once for both points.
  int models = 0, lattices = 0;
  for (const auto& e : fs::directory_iterator(d / "cache" / "lrchain")) {
    if (e.path().extension() != ".so") continue;
    const std::string name = e.path().filename().string();
    models += name.rfind("model-", 0) == 0;
    lattices += name.rfind("lattice-", 0) == 0;
  }
  CHECK(models == 1);
  CHECK(lattices == 0);  // no separate lattice object (the kinds before ABI 4)
  // The results through the CSV view (this test program has no model compiler to load the sweep
  // with; the CSV holds each double as its shortest round-trip text).
  const auto rows = csv_rows(d / "r.csv");
  REQUIRE(rows.size() == 3);
  CHECK(rows[1].at("status") == "numerical_failure");
  CHECK(rows[1].at("measured_frequency").empty());
  CHECK(rows[2].at("status") == "ok");
  // Point 0 as a single run: exit 3 with the same reason; point 1: the same numbers, bit for bit.
  lrchain::test::write_text(d / "p0.toml", ring_base(model, "", "1"));
  const auto p0 = lrchain::test::run_lrchain({"simulate", "--config", (d / "p0.toml").string(), "--json"}, {}, cache);
  CHECK(p0.exit_code == 3);
  CHECK(p0.err.find("the plane wave broke up") != std::string::npos);
  lrchain::test::write_text(d / "p1.toml", ring_base(model, "", "1", "2"));
  const auto p1 = lrchain::test::run_lrchain({"simulate", "--config", (d / "p1.toml").string(), "--json"}, {}, cache);
  REQUIRE_MESSAGE(p1.exit_code == 0, p1.err);
  const auto j = nlohmann::json::parse(p1.out);
  CHECK(std::stod(rows[2].at("measured_frequency")) == j["amplitudes"][0]["measured_frequency"].get<double>());
  CHECK(std::stod(rows[2].at("predicted_frequency")) == j["amplitudes"][0]["predicted_frequency"].get<double>());
  CHECK(std::stod(rows[2].at("packet_speed")) == j["packet"]["measured_speed"].get<double>());
  CHECK(std::stod(rows[2].at("h")) == j["prediction"]["h"].get<double>());
  fs::remove_all(d);
}

namespace {

// The textbook diatomic chain's optical branch (masses 1 and m, spring K; Kittel ch. 4), per cell:
// omega^2 = K (s + sqrt(s^2 - 4 sin^2(theta/2) / m)), s = 1 + 1/m. Its curvature d^2 omega/dtheta^2
// by central differences; its zero does not depend on K (omega scales with sqrt(K)).
double textbook_optical_curvature(double m, double theta) {
  const auto omega = [m](double t) {
    const double s = 1 + 1 / m, q = std::sin(t / 2);
    return std::sqrt(s + std::sqrt(s * s - 4 * q * q / m));
  };
  const double step = 1e-4;
  return (omega(theta + step) - 2 * omega(theta) + omega(theta - step)) / (step * step);
}

}  // namespace

TEST_CASE("sweep of a model file: regime intervals over parameters.m of the diatomic chain equal lrchain regime intervals --model") {
  const fs::path d = scratch("regime");
  const SweepConfig c = write_sweep(d, "regime intervals",
                                    "experiment = \"regime intervals\"\nmodel = \"" + std::string(LRCHAIN_SOURCE_DIR) +
                                        "/models/diatomic_chain.toml\"\n[parameters]\nm = 2\n[regime]\nsamples = 512\n",
                                    "parameters.m", "2, 3");
  const Job job = make_job(c);
  REQUIRE(job.model_source() != nullptr);
  CHECK(job.has_parameter("parameters.m"));
  CHECK(job.has_parameter("regime.samples"));
  // The scalars and the rows' branch codes follow the model's branches (acoustic, then optical).
  CHECK(job.scalar_names().front() == "acoustic_intervals");
  CHECK(job.scalar_names().at(6) == "optical_intervals");
  CHECK(job.rows_legend().find("branch: 0 acoustic, 1 optical") != std::string::npos);
  const SweepResults r = run_on_two_threads(c, job);
  REQUIRE(r.finished() == 2);
  CHECK(r.failed() == 0);
  // Each point's intervals are the regime job's (what `lrchain regime intervals --model` runs) at
  // that m, bit for bit.
  std::vector<double> expected_rows;
  for (const double m : {2.0, 3.0}) {
    const auto model = std::make_shared<const lrchain::Model>(
        lrchain::jobs::ModelSource(std::string(LRCHAIN_SOURCE_DIR) + "/models/diatomic_chain.toml", "model", nullptr)
            .model({{"m", m}}));
    for (const std::size_t b : {0, 1}) {
      lrchain::jobs::RegimeIntervalsConfig config;
      config.lattice.model = model;
      config.branch = model->definition().branch_names.at(b);
      config.samples = 512;
      for (const auto& i : lrchain::jobs::run(config).structure.intervals) {
        expected_rows.insert(expected_rows.end(), {double(b), i.lo, i.hi});
      }
    }
  }
  std::vector<double> rows;  // branch, lo, hi of every row of both points
  const std::size_t columns = job.row_names().size();
  for (const auto& point : r.rows)
    for (std::size_t k = 0; k < point.size() / columns; ++k)
      for (std::size_t column = 0; column < 3; ++column) rows.push_back(point[k * columns + column]);
  CHECK(rows == expected_rows);
  // Independent check: at m = 2 the optical interval begins where the textbook optical branch's
  // curvature vanishes (measured 2.1922437; central differences: 1e-6).
  const auto [lo, hi] = boost::math::tools::bisect([](double t) { return textbook_optical_curvature(2, t); }, 1.5, 3.0,
                                                   [](double a, double b) { return std::abs(a - b) < 1e-10; });
  CHECK(scalar(r, "optical_first_lo", 0) == doctest::Approx((lo + hi) / 2).epsilon(1e-6));
  CHECK(scalar(r, "optical_last_hi", 0) == doctest::Approx(std::acos(-1.0)).epsilon(1e-12));
  fs::remove_all(d);
}

namespace {

// A dark continue base on Klein-Gordon with b = -1/2, 31 sites, 3 branch points, starting at `start`.
std::string kg_dark_base(const std::string& start) {
  return "experiment = \"dark continue\"\nmodel = \"" + std::string(LRCHAIN_SOURCE_DIR) +
         "/models/klein_gordon.toml\"\n[parameters]\nb = \"-1/2\"\n[dark]\n" + start + "\nsites = 31\npoints = 3\n";
}

}  // namespace

TEST_CASE("sweep of a model file: dark continue over parameters.b of Klein-Gordon equals the dark job on that model") {
  // b = -1/2 and -2/5 (soft on-site force): the theta = pi edge omega(pi) = sqrt(w0^2 + 4 C) =
  // sqrt(1.4) is defocusing with h_tilde < 0, so edge_offset starts the branch below it.
  const std::string model_file = std::string(LRCHAIN_SOURCE_DIR) + "/models/klein_gordon.toml";
  const fs::path d = scratch("dark");
  const SweepConfig c = write_sweep(d, "dark continue", kg_dark_base("edge_offset = 0.0132"), "parameters.b", "-0.5, -0.4");
  const Job job = make_job(c);
  REQUIRE(job.model_source() != nullptr);
  CHECK(job.has_parameter("parameters.b"));
  CHECK(job.has_parameter("dark.edge_offset"));
  const SweepResults r = run_on_two_threads(c, job);
  REQUIRE(r.finished() == 2);
  CHECK(r.failed() == 0);
  const double omega_pi = std::sqrt(1.4);  // the KG dispersion relation at theta = pi, C = 1/10, w0 = 1
  const lrchain::jobs::ModelSource source(model_file, "model", nullptr);
  for (const std::size_t point : {0, 1}) {
    CAPTURE(point);
    CHECK(scalar(r, "omega_edge", point) == doctest::Approx(omega_pi).epsilon(1e-14));
    CHECK(scalar(r, "start_omega_b", point) == doctest::Approx(omega_pi - 0.0132).epsilon(1e-14));
    CHECK(scalar(r, "branch_points", point) == 3);
    // The point is the dark job's branch step (what `lrchain dark continue --model` runs) at that b,
    // bit for bit.
    const lrchain::Model model = source.model({{"b", point == 0 ? -0.5 : -0.4}});
    lrchain::jobs::dark::DarkConfig config;
    config.step = lrchain::jobs::dark::DarkStep::branch;
    config.model = &model;
    config.kernels = source.lattice().kernels.get();
    config.omega_b = scalar(r, "start_omega_b", point);
    config.sites = 31;
    config.points = 3;
    const lrchain::jobs::dark::DarkResult single = lrchain::jobs::dark::run(config);
    REQUIRE(single.branch.points.size() == 3);
    const std::size_t columns = job.row_names().size();
    for (std::size_t k = 0; k < 3; ++k) {
      CHECK(r.rows[point][k * columns] == single.branch.points[k].omega_b);
      CHECK(r.rows[point][k * columns + 1] == single.branch.points[k].measures.norm_squared);
      CHECK(r.rows[point][k * columns + 5] == single.branch.points[k].floquet.max_modulus);
    }
  }
  fs::remove_all(d);
}

TEST_CASE("sweep of a model file: a dark continue point on the wrong side of the edge is invalid, naming [dark] omega_b") {
  const fs::path d = scratch("dark-branch");
  const SweepConfig c = write_sweep(d, "dark continue", kg_dark_base("omega_b = 1.17"), "dark.omega_b", "1.19, 1.17");
  const Job job = make_job(c);
  // omega_b = 1.19 lies above the edge sqrt(1.4) = 1.1832, on the side without breathers.
  const JobResult above = job.run(c.overrides(0)), below = job.run(c.overrides(1));
  CHECK(above.status == PointStatus::invalid);
  CHECK(above.reason.find("[dark] omega_b in") != std::string::npos);
  CHECK(below.status == PointStatus::ok);
  fs::remove_all(d);
}

#ifdef LRCHAIN_TEST_MPI
TEST_CASE("sweep of a model file: mpirun -n 2 on an empty model cache gives the threaded results of a user's file" *
          doctest::timeout(300)) {
  REQUIRE_MESSAGE(lrchain::program_in_path("mpirun"), "this build has MPI: mpirun (openmpi-bin) must be installed");
  // Rank 0 compiles tests/data/sine_gordon_poly.toml into the cache, then rank 1 loads it from there.
  const fs::path d = scratch("user-file-mpi");
  fs::copy_file(fs::path(LRCHAIN_SOURCE_DIR) / "tests" / "data" / "sine_gordon_poly.toml", d / "sine_gordon_poly.toml");
  lrchain::test::write_text(d / "base.toml", ring_base((d / "sine_gordon_poly.toml").string(), "", "1"));
  lrchain::test::write_text(d / "threads.toml", ring_sweep("parameters.C", "0.5, 2, 3", d / "threads.h5"));
  lrchain::test::write_text(d / "ranks.toml", ring_sweep("parameters.C", "0.5, 2, 3", d / "ranks.h5"));
  const std::string cache = "XDG_CACHE_HOME=" + (d / "cache").string();
  const auto ranks = lrchain::test::run_command({"mpirun", "-n", "2", "--oversubscribe", "--allow-run-as-root", "-x",
                                                 "XDG_CACHE_HOME", LRCHAIN_CLI, "sweep", "--config", (d / "ranks.toml").string(),
                                                 "--json", "--quiet", "--threads", "1"},
                                                {}, {cache});
  REQUIRE_MESSAGE(ranks.exit_code == 0, ranks.err);
  CHECK(nlohmann::json::parse(ranks.out)["ranks"] == 2);
  const auto threads = lrchain::test::run_lrchain({"sweep", "--config", (d / "threads.toml").string(), "--quiet", "--threads", "2"},
                                                  {}, {cache});
  REQUIRE_MESSAGE(threads.exit_code == 0, threads.err);
  auto by_ranks = csv_rows(d / "ranks.csv"), by_threads = csv_rows(d / "threads.csv");
  REQUIRE(by_ranks.size() == 4);
  REQUIRE(by_threads.size() == 4);
  for (std::size_t row = 1; row < 4; ++row) {
    by_ranks[row].erase("wall_seconds");
    by_threads[row].erase("wall_seconds");
    CHECK(by_ranks[row] == by_threads[row]);
  }
  CHECK(by_ranks[1].at("status") == "numerical_failure");
  fs::remove_all(d);
}
#endif
