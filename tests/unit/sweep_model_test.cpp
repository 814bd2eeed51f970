// Sweeps whose base is a model-file simulate config (`model = "models/fput.toml"`): any model
// parameter ("parameters.b") and any number key of the job ("bright.theta") is an axis, the model
// is loaded once per sweep, and each point equals the single run of `lrchain simulate --config`
// with that point's values, bit for bit (the same job function, jobs::simulate_model_bright, on the
// same doubles: the run is deterministic). Bad input (an unknown parameter axis, a missing model
// file) exits 2 with one line naming the file and writes nothing.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/jobs/model_experiment_config.hpp"
#include "lrchain/jobs/simulate/model_simulate_job.hpp"
#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"
#include "../support/run_lrchain.hpp"
#include "sweep_test_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain::jobs::sweep;

namespace {

fs::path scratch(const std::string& name) { return lrchain::test::sweep_scratch("sweep-model-test", name); }

const std::string fput_file = std::string(LRCHAIN_SOURCE_DIR) + "/models/fput.toml";

// examples/models/fput_bright.toml shortened: 401 sites, 10 T_b; `b` is the cubic coefficient.
std::string fput_bright_base(const std::string& b, const std::string& model = fput_file) {
  return "experiment = \"bright\"\nmodel = \"" + model + "\"\n[parameters]\na = \"1/4\"\nb = \"" + b +
         "\"\n[bright]\nbranch = \"acoustic\"\ntheta = \"pi/2\"\ndetuning = 1e-4\nsites = 401\nn0 = -100\nperiods = 10\n";
}

std::string sweep_over(const std::string& parameter, const std::string& values, const fs::path& output) {
  return "job = \"bright\"\nbase = \"base.toml\"\noutput = \"" + output.string() + "\"\n[[axis]]\nparameter = \"" +
         parameter + "\"\nvalues = [" + values + "]\n";
}

// The JSON summary `lrchain simulate --config` prints for the model config `text`, computed through
// the job function it calls (cli/src/simulate_model_bright.cpp), without files.
nlohmann::json single_run(const std::string& text) {
  const auto mc = lrchain::jobs::load_model_experiment_config(lrchain::config::Document::from_text(text, "single.toml"));
  const lrchain::Model model = lrchain::shipped_model("fput", mc.parameters);
  auto c = mc.bright;
  lrchain::jobs::prepare(model, c, mc.branch);
  const ModelFile file = load_shipped_model_file(fput_file);
  return lrchain::jobs::simulate_model_bright(model, *file.kernels, c, {}, {"", false, "csv"}).summary;
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
  lrchain::test::write_text(d / "base.toml", fput_bright_base("1/2"));
  lrchain::test::write_text(d / "s.toml", sweep_over("parameters.b", "0.5, 0.75", d / "r.h5"));
  const SweepConfig c = load_sweep_config(d / "s.toml");
  const Job job = make_job(c);
  REQUIRE(job.model_file() != nullptr);
  CHECK(job.model_file() == c.base_job->model_file());  // loaded once: the sweep's job shares it
  CHECK(job.has_parameter("parameters.a"));
  CHECK(job.has_parameter("parameters.b"));
  CHECK(job.has_parameter("bright.theta"));
  SweepRunOptions o;
  o.threads = 2;
  o.progress = false;
  run_sweep(c, job, o);
  const SweepResults r = read_results(c.output, c, job);
  REQUIRE(r.points == 2);
  CHECK(r.failed() == 0);
  CHECK(r.finished() == 2);
  check_equals_single_run(r, 0, single_run(fput_bright_base("0.5")));
  check_equals_single_run(r, 1, single_run(fput_bright_base("0.75")));
  // b changes the nonlinearity: h_tilde of the acoustic branch at pi/2 differs between the points,
  // and the breather stays within a percent of its ansatz over 10 T_b at both.
  CHECK(scalar(r, "h_tilde", 0) != scalar(r, "h_tilde", 1));
  CHECK(scalar(r, "max_E_x", 0) < 1e-2);
  CHECK(scalar(r, "max_E_x", 1) < 1e-2);
  fs::remove_all(d);
}

TEST_CASE("sweep of a model file: a bright.theta axis point equals the single run with that theta") {
  const fs::path d = scratch("theta-axis");
  lrchain::test::write_text(d / "base.toml", fput_bright_base("1/2"));
  lrchain::test::write_text(d / "s.toml", sweep_over("bright.theta", "1.2", d / "r.h5"));
  const SweepConfig c = load_sweep_config(d / "s.toml");
  const JobResult point = make_job(c).run(c.overrides(0));
  REQUIRE(point.status == PointStatus::ok);
  SweepResults r(make_job(c), 1);
  r.set(0, point);
  std::string single = fput_bright_base("1/2");
  single.replace(single.find("\"pi/2\""), 6, "1.2");
  check_equals_single_run(r, 0, single_run(single));
  fs::remove_all(d);
}

TEST_CASE("sweep of a model file: a value out of the model's range is an invalid point, the others run") {
  const fs::path d = scratch("range");
  lrchain::test::write_text(d / "base.toml", fput_bright_base("1/2"));
  lrchain::test::write_text(d / "s.toml", sweep_over("bright.theta", "4, 1.5", d / "r.h5"));
  const SweepConfig c = load_sweep_config(d / "s.toml");
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
