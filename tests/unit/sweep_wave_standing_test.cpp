// The "wave standing" sweep job: a point's scalars and rows are `lrchain wave standing`'s (jobs/wave_job.hpp,
// and the command's JSON) for the same options, bit for bit; at small amplitude Klein-Gordon's multipliers on the ring are the
// linear lattice's e^{+-2 pi i Omega(2 pi m / N) / omega}, and its cubic coefficient b moves omega^2 as
// the Lindstedt-Poincare expansion says; a point the job refuses is recorded invalid naming [wave]'s key;
// mpirun -n 2 gives the threads' results bit for bit.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <limits>
#include <numbers>
#include <string>

#include <nlohmann/json.hpp>

#include "lrchain/jobs/sweep/results_file.hpp"
#include "lrchain/jobs/sweep/sweep_config.hpp"
#include "lrchain/jobs/sweep/sweep_run.hpp"
#include "lrchain/jobs/wave_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "../support/run_lrchain.hpp"
#include "sweep_test_files.hpp"

namespace fs = std::filesystem;
using namespace lrchain;
using namespace lrchain::jobs::sweep;

using lrchain::test::run_sweep_file;
using lrchain::test::sweep_scalar;

namespace {

// Klein-Gordon's base: theta = 2 pi/5 on a ring of 10 sites.
constexpr const char* klein_gordon_base = "experiment = \"wave standing\"\nmodel = \"klein_gordon\"\n"
                                          "[wave]\ntheta = 1.2566370614359172\namplitude = 0.01\nring_sites = 10\n"
                                          "ramp = 2\n";

void write_sweep(const fs::path& d, const std::string& name, const std::string& axis, const std::string& values) {
  lrchain::test::write_text(d / (name + ".toml"), "job = \"wave standing\"\nbase = \"base.toml\"\noutput = \"" +
                                                       (d / (name + ".h5")).string() + "\"\n[[axis]]\nparameter = \"" +
                                                       axis + "\"\nvalues = " + values + "\n");
}

}  // namespace

TEST_CASE("sweep wave standing: a point is the standing-wave job's result, and Klein-Gordon's linear multipliers" *
          doctest::test_suite("fast")) {
  const fs::path d = lrchain::test::sweep_scratch("sweep-standing", "kg");
  lrchain::test::write_text(d / "base.toml", klein_gordon_base);
  write_sweep(d, "s", "wave.amplitude", "[0.01, 0.3]");
  const SweepResults r = run_sweep_file(d / "s.toml");
  const Model kg = shipped_model("klein_gordon");
  for (std::size_t p = 0; p < 2; ++p) {
    CAPTURE(p);
    REQUIRE(r.status[p] == std::int8_t(PointStatus::ok));
    jobs::wave::WaveConfig c;
    c.step = jobs::wave::WaveStep::standing;
    c.model = &kg;
    c.kernels = &sim::lattice_kernels_of(kg);
    c.theta = 2 * std::numbers::pi / 5;
    c.amplitude = p == 0 ? 0.01 : 0.3;
    c.ring_sites = 10;
    c.ramp = 2;
    const jobs::wave::WaveResult w = jobs::wave::run(c);  // what `lrchain wave standing` runs
    REQUIRE(!w.failure);
    const auto& wave = w.standing.back();
    const auto& f = *w.standing_floquet;
    CHECK(sweep_scalar(r, "omega", p) == wave.omega);
    CHECK(sweep_scalar(r, "omega_shift", p) == wave.omega - wave.omega_linear);
    CHECK(sweep_scalar(r, "largest_modulus", p) == f.largest_modulus);
    CHECK(sweep_scalar(r, "stable", p) == (f.stable ? 1 : 0));
    CHECK(sweep_scalar(r, "ring_theta", p) == w.theta);
    CHECK(sweep_scalar(r, "period_sites", p) == 5);  // theta = 2 pi 2/10: 5 sites
    REQUIRE(r.rows[p].size() == 3 * f.multipliers.size());
    for (std::size_t i = 0; i < f.multipliers.size(); ++i) {
      CHECK(r.rows[p][3 * i] == f.multipliers[i].real());
      CHECK(r.rows[p][3 * i + 1] == f.multipliers[i].imag());
    }
  }
  // The command itself (its JSON prints every double to round-trip): the same numbers.
  const auto cli = lrchain::test::run_lrchain({"wave", "standing", "--model", "klein_gordon", "--theta", "2*pi/5",
                                               "--amplitude", "0.3", "--ramp", "2", "--ring-sites", "10", "--json"});
  REQUIRE_MESSAGE(cli.exit_code == 0, cli.err);
  const nlohmann::json printed = nlohmann::json::parse(cli.out).at("standing");
  CHECK(printed.at("omega").get<double>() == sweep_scalar(r, "omega", 1));
  CHECK(printed.at("floquet").at("largest_modulus").get<double>() == sweep_scalar(r, "largest_modulus", 1));
  CHECK(printed.at("waves").back().at("residual").get<double>() == sweep_scalar(r, "residual", 1));
  for (std::size_t i = 0; i < 20; ++i) {
    CHECK(printed.at("floquet").at("re").at(i).get<double>() == r.rows[1][3 * i]);
    CHECK(printed.at("floquet").at("im").at(i).get<double>() == r.rows[1][3 * i + 1]);
  }
  // The small wave: the linear lattice's multipliers. Each ring mode k_m = 2 pi m / N (m = 0..N-1) of
  // u'' = C (u[n+1] - 2u[n] + u[n-1]) - w0^2 u oscillates at Omega(k)^2 = w0^2 + 4C sin^2(k/2) (C = 1/10,
  // w0 = 1: models/klein_gordon.toml), so over the wave's period 2 pi/omega it turns by e^{+-2 pi i Omega/omega}.
  // The wave perturbs them by O(A^2) (its shift, 1.1e-5 at A = 0.01, docs/waves.md): the farthest was 9.6e-5
  // from its linear value; C = 0.101 instead of 0.1 would put one 1e-2 away.
  const double omega = sweep_scalar(r, "omega", 0);
  REQUIRE(r.rows[0].size() == 3 * 20);
  for (int m = 0; m < 10; ++m)
    for (int sign : {1, -1}) {
      const double k = 2 * std::numbers::pi * m / 10, Omega = std::sqrt(1 + 0.4 * std::pow(std::sin(k / 2), 2));
      const std::complex<double> expected = std::polar(1.0, sign * 2 * std::numbers::pi * Omega / omega);
      double nearest = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < 20; ++i)
        nearest = std::min(nearest, std::abs(std::complex<double>(r.rows[0][3 * i], r.rows[0][3 * i + 1]) - expected));
      CAPTURE(m);
      CHECK(nearest < 1e-3);
    }
  CHECK(sweep_scalar(r, "stable", 0) == 1);
  CHECK(sweep_scalar(r, "growth_rate", 0) == 0);
  CHECK(std::abs(sweep_scalar(r, "largest_modulus", 0) - 1) < 1e-6);
  fs::remove_all(d);
}

TEST_CASE("sweep wave standing: theta moving to pi on the ring is invalid, naming [wave] theta" *
          doctest::test_suite("fast")) {
  const fs::path d = lrchain::test::sweep_scratch("sweep-standing", "refused");
  lrchain::test::write_text(d / "base.toml", klein_gordon_base);
  write_sweep(d, "s", "wave.theta", "[1.2566370614359172, 3.1]");
  const SweepResults r = run_sweep_file(d / "s.toml");
  CHECK(r.status[0] == std::int8_t(PointStatus::ok));
  CHECK(r.status[1] == std::int8_t(PointStatus::invalid));
  CHECK(r.reasons[1].find("[wave] theta") != std::string::npos);
  fs::remove_all(d);
}

TEST_CASE("sweep wave standing: a model parameter as an axis, Klein-Gordon's b moves omega^2 by 9 b A^2 / 16" *
          doctest::test_suite("fast")) {
  const fs::path d = lrchain::test::sweep_scratch("sweep-standing", "b");
  lrchain::test::write_text(d / "base.toml", klein_gordon_base);
  write_sweep(d, "s", "parameters.b", "[0.5, -0.5]");
  const SweepResults r = run_sweep_file(d / "s.toml");
  REQUIRE(r.status[0] == std::int8_t(PointStatus::ok));
  REQUIRE(r.status[1] == std::int8_t(PointStatus::ok));
  // The Lindstedt-Poincare expansion of Klein-Gordon's standing wave (docs/waves.md, "The small-amplitude
  // frequency"): omega^2 - Omega^2 = A^2 [9b/16 - (terms in a only)] + O(A^4), so two values of b at the
  // same A differ by 9 (b1 - b2) A^2 / 16 = 5.625e-5 at A = 0.01 (measured 5.62509e-5: the O(A^4) rest).
  CHECK(sweep_scalar(r, "omega_linear", 0) == sweep_scalar(r, "omega_linear", 1));  // b is cubic: not in Omega
  const double difference = std::pow(sweep_scalar(r, "omega", 0), 2) - std::pow(sweep_scalar(r, "omega", 1), 2);
  MESSAGE("omega^2(b = 1/2) - omega^2(b = -1/2) = " << difference << ", Lindstedt-Poincare 5.625e-5");
  CHECK(difference == doctest::Approx(9.0 / 16 * 0.01 * 0.01).epsilon(1e-3));
  fs::remove_all(d);
}

#ifdef LRCHAIN_TEST_MPI
TEST_CASE("sweep wave standing: mpirun -n 2 gives the 1-rank results and rows bit for bit") {
  REQUIRE_MESSAGE(lrchain::program_in_path("mpirun"), "this build has MPI: mpirun (openmpi-bin) must be installed");
  const fs::path d = lrchain::test::sweep_scratch("sweep-standing", "mpi");
  lrchain::test::write_text(d / "base.toml", klein_gordon_base);
  for (const char* name : {"threads", "ranks"}) write_sweep(d, name, "wave.amplitude", "[0.01, 0.1, 0.3]");
  const SweepResults threads = run_sweep_file(d / "threads.toml");
  const SweepResults ranks = lrchain::test::run_sweep_on_two_ranks(d / "ranks.toml");
  CHECK(lrchain::test::same_bits(threads, ranks));
  fs::remove_all(d);
}
#endif
