// The "dark continue" and "regime intervals" sweep jobs: a point's scalars and rows equal what
// `lrchain dark continue` and `lrchain regime intervals` print for the same options (the expected
// values are those direct runs); the rows survive MPI-free resuming through the results file; bad
// base configs and axes exit 2 naming the key and write nothing.
#include <doctest/doctest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"
#include "../support/run_lrchain.hpp"
#include "sweep_test_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain::jobs::sweep;

namespace {

fs::path scratch(const std::string& name) { return lrchain::test::sweep_scratch("sweep-study", name); }
void write(const fs::path& f, const std::string& text) { lrchain::test::write_text(f, text); }

// A short bond-centred branch of the paper's chain on 21 sites from omega_b = 2.44 (edge 2.44949).
const char* dark_base = R"(experiment = "dark continue"
[model]
rho = "1/3"
[dark]
omega_b = 2.44
sites = 21
points = 6
ds = 0.1
)";

const char* regime_base = R"(experiment = "regime intervals"
[model]
rho = "1/3"
)";

double scalar(const SweepResults& r, const std::string& name, std::size_t point) {
  const auto it = std::find(r.scalar_names.begin(), r.scalar_names.end(), name);
  REQUIRE(it != r.scalar_names.end());
  return r.scalars[std::size_t(it - r.scalar_names.begin()) * r.points + point];
}

SweepResults run_in_process(const fs::path& sweep_file, int threads) {
  const SweepConfig c = load_sweep_config(sweep_file);
  const Job job = make_job(c);
  SweepRunOptions o;
  o.threads = threads;
  o.progress = false;
  run_sweep(c, job, o);
  return read_results(c.output, c, job);
}

}  // namespace

TEST_CASE("sweep dark continue: a point's scalars and rows equal `lrchain dark continue`'s output") {
  const fs::path d = scratch("dark");
  write(d / "base.toml", dark_base);
  write(d / "s.toml", "job = \"dark continue\"\nbase = \"base.toml\"\noutput = \"" + (d / "s.h5").string() +
                          "\"\n[[axis]]\nparameter = \"model.rho\"\nvalues = [0.3333333333333333, 1]\n");
  // rho = 1: the optical edge is omega(pi) = 2.2882 (docs/dark-breathers.md), so omega_b = 2.44 is not
  // below it: the point is invalid.
  const SweepResults r = run_in_process(d / "s.toml", 2);
  REQUIRE(r.status[0] == std::int8_t(PointStatus::ok));
  CHECK(r.status[1] == std::int8_t(PointStatus::invalid));
  CHECK(r.reasons[1].find("omega") != std::string::npos);

  const auto cli = lrchain::test::run_lrchain(
      {"dark", "continue", "--rho", "1/3", "--omega-b", "2.44", "--sites", "21", "--points", "6", "--ds", "0.1"});
  REQUIRE_MESSAGE(cli.exit_code == 0, cli.err);
  const auto j = nlohmann::json::parse(cli.out);
  CHECK(scalar(r, "branch_points", 0) == j["points"].get<double>());
  CHECK(scalar(r, "turning_points", 0) == double(j["turning_points"].size()));
  if (!j["turning_points"].empty()) CHECK(scalar(r, "first_turning_point", 0) == j["turning_points"][0].get<double>());
  CHECK(scalar(r, "max_E_b", 0) == j["max_E_b"].get<double>());
  CHECK(scalar(r, "omega_edge", 0) == j["omega_edge"].get<double>());
  CHECK(scalar(r, "newton_iterations", 0) == double(j["newton_residuals"].size()));
  // The progress lines on stderr: "point  k omega_b = W norm^2 = S KIND max|lambda| = M".
  std::istringstream lines(cli.err);
  std::string line;
  int points = 0, stable = 0, real = 0, oscillatory = 0;
  double max_modulus = 0;
  const std::size_t columns = r.row_names.size();
  while (std::getline(lines, line)) {
    if (line.rfind("point", 0) != 0) continue;
    int k = 0;
    double w = 0, norm = 0, m = 0;
    char kind[64] = {};
    REQUIRE(std::sscanf(line.c_str(), "point %d omega_b = %lf norm^2 = %lf %63s max|lambda| = %lf", &k, &w, &norm, kind, &m) == 5);
    REQUIRE(std::size_t(points + 1) * columns <= r.rows[0].size());
    const double* row = r.rows[0].data() + std::size_t(points) * columns;
    CHECK(std::abs(row[0] - w) <= 6e-7);
    CHECK(std::abs(row[1] - norm) <= 6e-6);   // %.5f
    CHECK(std::abs(row[5] - m) <= 6e-6);      // max_modulus, %.5f
    const std::string k_text = kind;
    CHECK((row[4] == 0) == (k_text == "stable"));
    CHECK((int(row[4]) & 1) == (k_text.find("real") != std::string::npos ? 1 : 0));
    CHECK((int(row[4]) & 4) == (k_text.find("oscillatory") != std::string::npos ? 4 : 0));
    stable += k_text == "stable";
    real += k_text.find("real") != std::string::npos;
    oscillatory += k_text.find("oscillatory") != std::string::npos;
    max_modulus = std::max(max_modulus, m);
    ++points;
  }
  CHECK(points == j["points"].get<int>());
  CHECK(r.rows[0].size() == std::size_t(points) * columns);
  CHECK(scalar(r, "stable_points", 0) == stable);
  CHECK(scalar(r, "real_unstable_points", 0) == real);
  CHECK(scalar(r, "oscillatory_unstable_points", 0) == oscillatory);
  CHECK(std::abs(scalar(r, "max_floquet_modulus", 0) - max_modulus) <= 6e-6);
  CHECK(scalar(r, "stable_windows", 0) + scalar(r, "unstable_windows", 0) >= 1);
  CHECK(r.rows[1].empty());
  CHECK(fs::exists(d / "s.rows.csv"));
  fs::remove_all(d);
}

TEST_CASE("sweep regime intervals: the interval ends equal `lrchain regime intervals`'s for both branches") {
  const fs::path d = scratch("regime");
  write(d / "base.toml", regime_base);
  write(d / "s.toml", "job = \"regime intervals\"\nbase = \"base.toml\"\noutput = \"" + (d / "s.h5").string() +
                          "\"\n[[axis]]\nparameter = \"model.rho\"\nvalues = [0.3333333333333333, 1, 10]\n");
  const SweepResults r = run_in_process(d / "s.toml", 2);
  const char* rhos[] = {"1/3", "1", "10"};
  const std::size_t columns = r.row_names.size();
  for (std::size_t p = 0; p < 3; ++p) {
    CAPTURE(rhos[p]);
    REQUIRE(r.status[p] == std::int8_t(PointStatus::ok));
    std::size_t row = 0;
    for (const std::string branch : {"optical", "acoustic"}) {
      const auto cli = lrchain::test::run_lrchain({"regime", "intervals", "--rho", rhos[p], "--branch", branch});
      REQUIRE_MESSAGE(cli.exit_code == 0, cli.err);
      const auto iv = nlohmann::json::parse(cli.out)["intervals"];
      CHECK(scalar(r, branch + "_intervals", p) == double(iv.size()));
      double length = 0;
      for (const auto& i : iv) {
        REQUIRE((row + 1) * columns <= r.rows[p].size());
        const double* x = r.rows[p].data() + row * columns;
        CHECK(x[0] == (branch == "optical" ? 0 : 1));
        CHECK(x[1] == i["lo"].get<double>());
        CHECK(x[2] == i["hi"].get<double>());
        length += i["hi"].get<double>() - i["lo"].get<double>();
        ++row;
      }
      CHECK(scalar(r, branch + "_focusing_length", p) == doctest::Approx(length).epsilon(1e-15));
      if (!iv.empty()) {
        CHECK(scalar(r, branch + "_first_lo", p) == iv.front()["lo"].get<double>());
        CHECK(scalar(r, branch + "_last_hi", p) == iv.back()["hi"].get<double>());
      }
    }
    CHECK(r.rows[p].size() == row * columns);
  }
  // At rho = 1/3 the optical focusing interval is (0, 1.8916) (docs/regime-maps.md).
  CHECK(scalar(r, "optical_first_hi", 0) == doctest::Approx(1.8916).epsilon(1e-4));
  fs::remove_all(d);
}

TEST_CASE("sweep dark continue / regime intervals: bad configs exit 2 naming the key, and write nothing") {
  const fs::path d = scratch("bad");
  write(d / "dark.toml", dark_base);
  write(d / "regime.toml", regime_base);
  write(d / "both.toml", std::string(dark_base) + "edge_offset = 0.01\n");
  write(d / "even.toml", "experiment = \"dark continue\"\n[dark]\nomega_b = 2.44\nsites = 20\n");
  write(d / "typo.toml", "experiment = \"dark continue\"\n[dark]\nomega_b = 2.44\npoints = 5\nsitse = 21\n");
  // The key `edge` of [dark] is now `branch` (one name per concept with `lrchain dark --branch`).
  write(d / "old_key.toml", "experiment = \"dark continue\"\n[dark]\nomega_b = 2.44\nedge = \"optical\"\n");
  const std::string out = "output = \"" + (d / "out" / "r.h5").string() + "\"\n";
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {"job = \"dark continue\"\nbase = \"dark.toml\"\n" + out + "[[axis]]\nparameter = \"dark.omgea_b\"\nvalues = [2.44]\n",
       "did you mean 'dark.omega_b'"},
      {"job = \"dark continue\"\nbase = \"regime.toml\"\n" + out + "[[axis]]\nparameter = \"model.rho\"\nvalues = [1]\n",
       "not \"dark continue\""},
      {"job = \"dark continue\"\nbase = \"both.toml\"\n" + out + "[[axis]]\nparameter = \"model.rho\"\nvalues = [1]\n",
       "edge_offset"},
      {"job = \"dark continue\"\nbase = \"even.toml\"\n" + out + "[[axis]]\nparameter = \"model.rho\"\nvalues = [1]\n",
       "sites"},
      {"job = \"dark continue\"\nbase = \"typo.toml\"\n" + out + "[[axis]]\nparameter = \"model.rho\"\nvalues = [1]\n",
       "did you mean 'sites'"},
      {"job = \"dark continue\"\nbase = \"old_key.toml\"\n" + out + "[[axis]]\nparameter = \"model.rho\"\nvalues = [1]\n",
       "old_key.toml:4 was renamed: use 'branch'"},
      {"job = \"regime intervals\"\nbase = \"regime.toml\"\n" + out + "[[axis]]\nparameter = \"regime.samples\"\nvalues = []\n",
       "'values'"},
      {"job = \"dark continue\"\nbase = \"dark.toml\"\nfigure = \"stability\"\n" + out +
           "[[axis]]\nparameter = \"model.rho\"\nvalues = [1]\n[[axis]]\nparameter = \"dark.sites\"\nvalues = [21]\n",
       "'figure'"},
  };
  for (const auto& k : cases) {
    CAPTURE(k.text);
    write(d / "s.toml", k.text);
    const auto r = lrchain::test::run_lrchain({"sweep", "--config", (d / "s.toml").string()});
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(k.expected) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(!fs::exists(d / "out"));
  }
  fs::remove_all(d);
}

#ifdef LRCHAIN_TEST_MPI
TEST_CASE("sweep dark continue: mpirun -n 2 gives the 1-rank results and rows bit for bit") {
  REQUIRE_MESSAGE(lrchain::program_in_path("mpirun"), "this build has MPI: mpirun (openmpi-bin) must be installed");
  const fs::path d = scratch("dark-mpi");
  write(d / "base.toml", dark_base);
  for (const char* name : {"threads", "ranks"})
    write(d / (std::string(name) + ".toml"), "job = \"dark continue\"\nbase = \"base.toml\"\noutput = \"" +
                                                 (d / (std::string(name) + ".h5")).string() +
                                                 "\"\n[[axis]]\nparameter = \"dark.omega_b\"\nvalues = [2.44, 2.442, 2.438]\n");
  const SweepResults threads = run_in_process(d / "threads.toml", 2);
  const SweepResults ranks = lrchain::test::run_sweep_on_two_ranks(d / "ranks.toml");
  CHECK(lrchain::test::same_bits(threads, ranks));
  fs::remove_all(d);
}
#endif
