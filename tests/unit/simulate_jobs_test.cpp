// The simulate jobs through the library (jobs/simulate/simulate_job.hpp, model_simulate_job.hpp):
// the files and summary a run writes, the checkpoint placement, and the refusals that come before
// anything is written.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/simulate/model_simulate_job.hpp"
#include "lrchain/jobs/simulate/simulate_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "short_runs.hpp"

using namespace lrchain;
namespace fs = std::filesystem;
using lrchain::test::refused_parameter;
using lrchain::test::short_drive;

namespace {

// An empty scratch directory of this process (removed first if an earlier run left it).
fs::path scratch_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("lrchain-simulate-jobs-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(d);
  return d;
}

}  // namespace

TEST_CASE("simulate job: a drive run writes its files and summary, its checkpoint goes to DIR/checkpoint.bin") {
  const fs::path dir = scratch_dir("drive");
  const sim::DriveRunConfig c = short_drive();
  const auto report = jobs::simulate(c, {dir.string(), false, "csv"});
  CHECK(fs::is_regular_file(dir / "series.csv"));
  CHECK(fs::is_regular_file(dir / "summary.json"));
  CHECK_FALSE(fs::exists(dir / "energy.png"));  // no figures asked for
  const nlohmann::json& j = report.summary;
  CHECK(j.at("experiment") == "drive");
  CHECK(j.at("out") == dir.string());
  // Checkpoints would go to DIR/checkpoint.bin; none asked for (no file, no interval): none written.
  CHECK(report.checkpoint_file == (dir / "checkpoint.bin").string());
  CHECK(j.at("checkpoint_file") == report.checkpoint_file);
  CHECK(j.at("checkpoints_written") == 0);
  CHECK_FALSE(fs::exists(dir / "checkpoint.bin"));
  CHECK(j.at("t_end").get<double>() == doctest::Approx(60).epsilon(1e-12));
  // The carrier theta solves omega_+(theta) = omega0 on the optical branch (the dispersion relation
  // eq:dispersion evaluated independently of the run).
  const double theta = j.at("theta").get<double>();
  CHECK(dispersion_omega(c.params, Branch::optical, theta) == doctest::Approx(c.omega0).epsilon(1e-9));
  // summary.json holds the summary the job returns.
  std::ifstream in(dir / "summary.json");
  const nlohmann::json written = nlohmann::json::parse(in);
  CHECK(written.at("theta") == j.at("theta"));
  CHECK(written.at("checkpoint_file") == j.at("checkpoint_file"));
  fs::remove_all(dir);
}

TEST_CASE("simulate job: a bad checkpoint path or an earlier run's checkpoint is refused before anything is written") {
  const fs::path dir = scratch_dir("refusals");
  sim::DriveRunConfig c = short_drive();
  c.checkpoint_file = (dir / "no-such-directory" / "c.bin").string();
  CHECK(refused_parameter([&] { jobs::simulate(c, {dir.string(), false, "csv"}); }) == "checkpoint");
  CHECK_FALSE(fs::exists(dir));  // the output directory was not even created
  // An earlier run's checkpoint in the output directory: a new run (no restart file) is refused.
  fs::create_directories(dir);
  std::ofstream(dir / "checkpoint.bin") << "earlier";
  c.checkpoint_file.clear();
  CHECK(refused_parameter([&] { jobs::simulate(c, {dir.string(), false, "csv"}); }) == "checkpoint");
  CHECK_FALSE(fs::exists(dir / "series.csv"));
  // A bad option is refused by its Config key.
  c = short_drive();
  c.amplitude = -1;
  CHECK(refused_parameter([&] { jobs::validate(c, ""); }) == "amplitude");
  fs::remove_all(dir);
}

TEST_CASE("simulate job: the model ring job labels its summary and measures the derived frequency shift") {
  const Model model = shipped_model("fput");
  sim::RingRunConfig c;
  c.theta = std::numbers::pi / 2;
  c.amplitudes = {0.02, 0.01};
  CHECK_THROWS_AS(jobs::prepare(model, c, "no-such-branch"), InvalidParameter);
  jobs::prepare(model, c, "acoustic");
  const auto report =
      jobs::simulate_ring(model, sim::lattice_kernels_of(model), c, {{{"name", "fput"}}, "a ring"}, {});
  const nlohmann::json& j = report.summary;
  CHECK(j.at("name") == "a ring");
  CHECK(j.at("model").at("name") == "fput");
  CHECK_FALSE(j.contains("out"));
  // The lattice's frequency at U = 0.02 against omega + h U^2/4 from the derived h: O(U^2) apart,
  // below 1 % (the bound of tests/validation/model_ring_test.cpp).
  REQUIRE(j.at("amplitudes").size() == 2);
  CHECK(j.at("amplitudes")[0].at("relative_disagreement").get<double>() < 0.01);
}
