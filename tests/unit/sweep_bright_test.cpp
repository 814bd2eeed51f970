// The "bright floquet" and "bright continue" sweep jobs: a point's scalars and rows are the bright-breather
// job's (jobs/bright_breather_job.hpp) for the same options, bit for bit; edge_offset starts omega_b that far
// beyond the focusing edge; the FPU chain's Sievers-Takeno mode comes out unstable with the multiplier the
// job's own test and Sandusky, Page & Schmidt, PRB 46, 6161 (1992) give; a point the job refuses is recorded
// invalid naming [bright]'s key; the paper's chain with [model] is a base too.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/bright_breather_job.hpp"
#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_figure.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "../support/run_lrchain.hpp"
#include "sweep_test_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain;
using namespace lrchain::jobs::sweep;
using lrchain::test::run_sweep_file;
using lrchain::test::sweep_scalar;
namespace bb = lrchain::jobs::bright_breather;

namespace {

// A sweep file of `job` over `axis` with `values`, its base `base` in `d`.
void write_sweep(const fs::path& d, const std::string& job, const std::string& base, const std::string& axis,
                 const std::string& values) {
  lrchain::test::write_text(d / "base.toml", base);
  lrchain::test::write_text(d / "s.toml", "job = \"" + job + "\"\nbase = \"base.toml\"\noutput = \"" + (d / "s.h5").string() +
                                              "\"\n[[axis]]\nparameter = \"" + axis + "\"\nvalues = " + values + "\n");
}

}  // namespace

TEST_CASE("sweep bright floquet: a point is the bright job's breather, bit for bit, a band frequency is invalid" *
          doctest::test_suite("fast")) {
  const fs::path d = lrchain::test::sweep_scratch("sweep-bright", "kg");
  write_sweep(d, "bright floquet", "experiment = \"bright floquet\"\nmodel = \"klein_gordon\"\n[bright]\nomega_b = 1.2\nsites = 31\n",
              "bright.omega_b", "[1.2, 1.21, 1.1]");
  const SweepResults r = run_sweep_file(d / "s.toml");
  const Model kg = shipped_model("klein_gordon");
  for (std::size_t p = 0; p < 2; ++p) {
    CAPTURE(p);
    REQUIRE(r.status[p] == std::int8_t(PointStatus::ok));
    bb::BrightBreatherConfig c;
    c.step = bb::BrightStep::floquet;
    c.model = &kg;
    c.kernels = &sim::lattice_kernels_of(kg);
    c.omega_b = p == 0 ? 1.2 : 1.21;
    c.sites = 31;
    const bb::BrightBreatherResult b = bb::run(c);
    REQUIRE(b.floquet);
    CHECK(sweep_scalar(r, "omega_b", p) == c.omega_b);
    CHECK(sweep_scalar(r, "converged", p) == 1);
    CHECK(sweep_scalar(r, "newton_iterations", p) == double(b.newton.history.size() - 1));
    CHECK(sweep_scalar(r, "residual", p) == b.newton.history.back().residual);
    CHECK(sweep_scalar(r, "peak", p) == b.profile.peak);
    CHECK(sweep_scalar(r, "width", p) == b.profile.width);
    CHECK(sweep_scalar(r, "max_nontrivial_modulus", p) == b.floquet->max_nontrivial_modulus);
    CHECK(sweep_scalar(r, "det_defect", p) == b.floquet->det_defect);
    // the site-centred Klein-Gordon breather above the band is stable (docs/bright-breathers.md at 1.19)
    CHECK(sweep_scalar(r, "stable", p) == 1);
    CHECK(sweep_scalar(r, "stability", p) == 0);
    // the top band edge of klein_gordon: sqrt(w0^2 + 4 C) = sqrt(1.4) at theta = pi
    CHECK(sweep_scalar(r, "omega_edge", p) == doctest::Approx(std::sqrt(1.4)).epsilon(1e-14));
  }
  // omega_b = 1.1 lies inside the band [1, sqrt(1.4)]: invalid, naming the key as [bright] spells it
  CHECK(r.status[2] == std::int8_t(PointStatus::invalid));
  CHECK(r.reasons[2].find("[bright] omega_b") != std::string::npos);
  fs::remove_all(d);
}

TEST_CASE("sweep bright floquet: edge_offset places the FPU chain's Sievers-Takeno mode" * doctest::test_suite("fast")) {
  const fs::path d = lrchain::test::sweep_scratch("sweep-bright", "fput");
  // fput with a = 0: the acoustic band [0, 2], focusing top edge, h_tilde = 6 > 0: omega_b = 2 + edge_offset
  write_sweep(d, "bright floquet",
              "experiment = \"bright floquet\"\nmodel = \"fput\"\n[parameters]\na = 0\n[bright]\ncenter = \"site\"\n"
              "edge_offset = 0.2\nsites = 41\n",
              "bright.edge_offset", "[0.2, -0.1]");
  const SweepResults r = run_sweep_file(d / "s.toml");
  REQUIRE(r.status[0] == std::int8_t(PointStatus::ok));
  CHECK(sweep_scalar(r, "omega_b", 0) == doctest::Approx(2.2).epsilon(1e-14));
  // the Sievers-Takeno mode at omega_b = 2.2: one real multiplier 1.02824 (docs/bright-breathers.md; the
  // bright job's test); Sandusky, Page & Schmidt (1992) find it unstable
  CHECK(sweep_scalar(r, "stable", 0) == 0);
  CHECK(sweep_scalar(r, "stability", 0) == 1);
  CHECK(sweep_scalar(r, "max_nontrivial_modulus", 0) == doctest::Approx(1.02824).epsilon(1e-5));
  CHECK(r.status[1] == std::int8_t(PointStatus::invalid));
  CAPTURE(r.reasons[1]);
  CHECK(r.reasons[1].find("edge_offset") != std::string::npos);
  fs::remove_all(d);
}

TEST_CASE("sweep bright continue: a point is the bright job's branch, rows and folds, bit for bit" * doctest::test_suite("fast")) {
  const fs::path d = lrchain::test::sweep_scratch("sweep-bright", "branch");
  write_sweep(d, "bright continue",
              "experiment = \"bright continue\"\nmodel = \"klein_gordon\"\n[bright]\nomega_b = 1.2\nsites = 31\npoints = 4\n",
              "parameters.C", "[0.1, 0.08]");
  const SweepResults r = run_sweep_file(d / "s.toml");
  for (std::size_t p = 0; p < 2; ++p) {
    CAPTURE(p);
    REQUIRE(r.status[p] == std::int8_t(PointStatus::ok));
    const Model kg = shipped_model("klein_gordon", {{"C", p == 0 ? 0.1 : 0.08}});
    bb::BrightBreatherConfig c;
    c.step = bb::BrightStep::branch;
    c.model = &kg;
    c.kernels = &sim::lattice_kernels_of(kg);
    c.omega_b = 1.2;
    c.sites = 31;
    c.points = 4;
    const bb::BrightBreatherResult b = bb::run(c);
    const std::size_t n = b.branch.points.size();
    REQUIRE(n == 4);
    CHECK(sweep_scalar(r, "branch_points", p) == double(n));
    CHECK(sweep_scalar(r, "parameter_high", p) == b.branch.points.back().omega_b);  // omega_b rises away from the edge
    CHECK(sweep_scalar(r, "folds", p) == 0);  // monotone near the edge (docs/bright-breathers.md: no bifurcations)
    CHECK(sweep_scalar(r, "stable_points", p) == 4);
    const std::size_t columns = r.row_names.size();
    REQUIRE(r.rows[p].size() == columns * n);
    for (std::size_t k = 0; k < n; ++k) {
      CHECK(r.rows[p][k * columns + 0] == b.branch.points[k].omega_b);
      CHECK(r.rows[p][k * columns + 2] == b.branch_profiles[k].peak);
      CHECK(r.rows[p][k * columns + 9] == b.branch_floquets[k].max_nontrivial_modulus);
    }
  }
  CHECK(sweep_scalar(r, "omega_edge", 0) == doctest::Approx(std::sqrt(1.4)).epsilon(1e-14));
  CHECK(sweep_scalar(r, "omega_edge", 1) == doctest::Approx(std::sqrt(1.32)).epsilon(1e-14));  // sqrt(1 + 4 C)
  fs::remove_all(d);
}

TEST_CASE("sweep bright floquet: the paper's chain as a base, refused: it has no focusing band edge" * doctest::test_suite("fast")) {
  // The resonant chain's band edges are defocusing or degenerate (`lrchain bright solve` lists them):
  // the base is refused before anything runs, naming [bright]'s key and the edges checked.
  const fs::path d = lrchain::test::sweep_scratch("sweep-bright", "chain");
  for (const char* start : {"omega_b = 2.5", "edge_offset = 0.01"}) {
    CAPTURE(start);
    write_sweep(d, "bright floquet", std::string("experiment = \"bright floquet\"\n[model]\nrho = \"1/3\"\n[bright]\n") + start + "\n",
                "model.rho", "[0.3333333333333333, 1]");
    std::string message;
    try {
      make_job(load_sweep_config(d / "s.toml"));
    } catch (const InputError& e) {
      message = e.what();
    }
    CHECK(message.find(std::string("[bright] ") + (start[0] == 'o' ? "omega_b" : "edge_offset") + " in ") != std::string::npos);
    CHECK(message.find("[bright] [bright]") == std::string::npos);
    CHECK(message.find("optical at theta = pi: defocusing") != std::string::npos);
  }
  fs::remove_all(d);
}

TEST_CASE("sweep bright continue: the FPU chain's Sievers-Takeno branch is the same at every b rescaled, and its figure" *
          doctest::test_suite("fast")) {
  // With a = 0 the force r + b r^3 is invariant under r -> r / sqrt(b'/b): the breather at a fixed omega_b
  // (edge_offset from the b-independent edge 2) rescales by sqrt(b / b') and its multipliers do not change.
  const fs::path d = lrchain::test::sweep_scratch("sweep-bright", "fput-branch");
  lrchain::test::write_text(d / "base.toml", "experiment = \"bright continue\"\nmodel = \"fput\"\n[parameters]\na = 0\n"
                                             "[bright]\nedge_offset = 0.2\ncenter = \"site\"\nsites = 41\npoints = 2\n");
  lrchain::test::write_text(d / "s.toml", "job = \"bright continue\"\nbase = \"base.toml\"\noutput = \"" + (d / "s.h5").string() +
                                              "\"\nfigure = \"stability\"\n[[axis]]\nparameter = \"parameters.b\"\n"
                                              "values = [0.5, 2]\n");
  const SweepResults r = run_sweep_file(d / "s.toml");
  REQUIRE(r.status[0] == std::int8_t(PointStatus::ok));
  REQUIRE(r.status[1] == std::int8_t(PointStatus::ok));
  const std::size_t columns = r.row_names.size();
  REQUIRE(r.row_names[2] == "peak");
  REQUIRE(r.row_names[9] == "max_modulus");
  // the first branch point: peak ratio sqrt(2 / 0.5) = 2, the same multiplier 1.02824 (docs/bright-breathers.md)
  CHECK(r.rows[0][2] / r.rows[1][2] == doctest::Approx(2).epsilon(1e-8));
  CHECK(r.rows[0][9] == doctest::Approx(r.rows[1][9]).epsilon(1e-8));
  CHECK(r.rows[0][9] == doctest::Approx(1.02824).epsilon(1e-5));
  CHECK(sweep_scalar(r, "real_unstable_points", 0) == double(r.rows[0].size() / columns));
  CHECK(sweep_scalar(r, "first_unstable", 0) == doctest::Approx(2.2).epsilon(1e-14));
  // figure = "stability": one line per branch point in its data file (the PNG needs gnuplot)
  const SweepConfig c = load_sweep_config(d / "s.toml");
  write_requested_figure(c, make_job(c));
  std::ifstream dat(d / "s_stability.dat");
  REQUIRE(dat.good());
  std::size_t lines = 0;
  for (std::string line; std::getline(dat, line);) lines += !line.empty() && line[0] != '#';
  CHECK(lines == (r.rows[0].size() + r.rows[1].size()) / columns);
  fs::remove_all(d);
}

#ifdef LRCHAIN_TEST_MPI
TEST_CASE("sweep bright continue: mpirun -n 2 gives the 1-rank results and rows bit for bit") {
  REQUIRE_MESSAGE(lrchain::program_in_path("mpirun"), "this build has MPI: mpirun (openmpi-bin) must be installed");
  const fs::path d = lrchain::test::sweep_scratch("sweep-bright", "mpi");
  lrchain::test::write_text(d / "base.toml", "experiment = \"bright continue\"\nmodel = \"fput\"\n[parameters]\na = 0\n"
                                             "[bright]\nedge_offset = 0.2\ncenter = \"site\"\nsites = 41\npoints = 2\n");
  for (const char* name : {"threads", "ranks"})
    lrchain::test::write_text(d / (std::string(name) + ".toml"),
                              "job = \"bright continue\"\nbase = \"base.toml\"\noutput = \"" + (d / (std::string(name) + ".h5")).string() +
                                  "\"\n[[axis]]\nparameter = \"bright.edge_offset\"\nvalues = [0.2, 0.25, 0.3]\n");
  const SweepResults threads = run_sweep_file(d / "threads.toml");
  const SweepResults ranks = lrchain::test::run_sweep_on_two_ranks(d / "ranks.toml");
  CHECK(lrchain::test::same_bits(threads, ranks));
  fs::remove_all(d);
}
#endif
