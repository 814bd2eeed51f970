// Resource estimates and checked counts of the lattice runs (resource_estimate.hpp, integrator.hpp,
// bright/drive/modulated validate): refusals name the parameter; the estimates bound what a run
// really stores and writes.
#include <doctest/doctest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "lrchain/errors.hpp"
#include "lrchain/jobs/output_files.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/drive_run.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/modulated_run.hpp"
#include "lrchain/sim/resource_estimate.hpp"
#include "short_runs.hpp"

using namespace lrchain;
using namespace lrchain::sim;
namespace fs = std::filesystem;
using lrchain::test::refused_parameter;

namespace {

BrightRunConfig small_bright() {
  BrightRunConfig c;
  c.params.rho = 1.0 / 3;
  c.theta = std::numbers::pi / 2;
  c.N = 100;
  c.periods = 4;
  c.sample_every = 0.25;
  c.spacetime_every = 1;
  c.snapshot_periods = {0, 2, 4};
  return c;
}

}  // namespace

TEST_CASE("srkn11b takes the fewest equal steps not longer than dt — a dt of 1e-300 is refused") {
  Params p;
  p.rho = 1.0 / 3;
  const DisplacementLattice chain(p, 20, DisplacementBoundary{});
  State s(chain.layout().size(), 0.0);
  s[10] = 0.01;
  IntegratorOptions o;
  o.stepper = StepperKind::srkn11b;
  o.dt = 1.0 / 32;  // [0, 1] in ceil(1 / dt) = 32 steps (the overflowing cast gave 16 at dt = 1e-300)
  auto observe = [](const State&, double) { return true; };
  const IntegrationStats st = integrate_observed(chain, s, {0.0, 1.0}, observe, o);
  CHECK(st.steps == 32);
  o.dt = 1e-300;
  CHECK(refused_parameter([&] { integrate_observed(chain, s, {0.0, 1.0}, observe, o); }) == "dt");
  o.dt = std::numeric_limits<double>::infinity();
  CHECK(refused_parameter([&] { integrate_observed(chain, s, {0.0, 1.0}, observe, o); }) == "dt");
}

TEST_CASE("sample counts that overflow an integer are refused, naming the option") {
  BrightRunConfig b = small_bright();
  b.periods = 1e300 * std::numbers::pi;
  CHECK(refused_parameter([&] { validate(b); }) == "periods");
  DriveRunConfig d;
  d.t_end = 1e308 * std::numbers::pi;  // inf
  CHECK(refused_parameter([&] { validate(d); }) == "t_end");
  d = DriveRunConfig{};
  d.amplitude = std::numeric_limits<double>::quiet_NaN();
  CHECK(refused_parameter([&] { validate(d); }) == "amplitude");
  ModulatedRunConfig m;
  m.epsilon = std::numeric_limits<double>::infinity();
  CHECK(refused_parameter([&] { validate(m); }) == "epsilon");
  m = ModulatedRunConfig{};
  m.sample_every = 1e-300;
  // (the sample-count check keeps the command's spelling: its message reads "samples (t-end / sample-every)")
  CHECK(refused_parameter([&] { validate(m); }) == "sample-every");
}

TEST_CASE("memory limits name the lattice size or the sampling, whichever dominates") {
  BrightRunConfig b = small_bright();
  CHECK(refused_parameter([&] { validate(b); }).empty());
  b.N = 1'000'000'000;  // 2e9 beads: terabytes
  CHECK(refused_parameter([&] { validate(b); }) == "sites");
  b = small_bright();
  b.sample_every = b.spacetime_every = 1e-9;  // 4e9 samples and space-time rows
  CHECK(refused_parameter([&] { validate(b); }) == "periods");
  b = small_bright();
  b.max_memory = 100'000;  // bytes: below the 0.2 MB estimate (0.12 MB for the state and rkf78 stages)
  CHECK(refused_parameter([&] { validate(b); }) == "sites");
  DriveRunConfig d;
  d.beads = 10'000'000'000;
  CHECK(refused_parameter([&] { validate(d); }) == "sites");
  ModulatedRunConfig m;
  m.checkpoint_every = 1e-7;
  CHECK(refused_parameter([&] { validate(m); }) == "checkpoint_every");
}

TEST_CASE("default snapshot times outside a short run are dropped, given ones are refused") {
  BrightRunConfig b = small_bright();
  b.snapshot_periods = default_bright_snapshot_periods();  // 0, 50.125, 200 T_b; the run is 4 T_b
  CHECK(snapshot_periods_in_run(b) == std::vector<double>{0.0});
  CHECK(refused_parameter([&] { validate(b); }).empty());
  b.snapshot_periods = {0, 5};
  CHECK(refused_parameter([&] { validate(b); }) == "snapshots");
  ModulatedRunConfig m;
  m.t_end = 1000;
  m.snapshot_times = {-1};
  CHECK(refused_parameter([&] { validate(m); }) == "snapshots");
}

TEST_CASE("the lattice-run estimate bounds what a bright run stores and writes") {
  // A real run (N = 100, 4 T_b): the record it keeps in memory and the files it writes must lie
  // below the estimate, and within a factor 4 of it (the estimate is for refusing absurd jobs,
  // not a loose guess).
  BrightRunConfig c = small_bright();
  c.integrator = IntegratorOptions{};  // rkf78: the stepper with the most stage vectors
  const ResourceEstimate e = estimate_resources(c);
  const BrightRunResult r = run_resonant_chain_bright(c);
  double stored = double(r.record.series.data.size()) * 8;
  for (const auto& f : r.record.fields) stored += double(f.values.size()) * 4 + double(f.times.size()) * 8;
  for (const auto& s : r.record.snapshots) stored += double(s.data.size()) * 8;
  stored += 32.0 * 202 * 19;  // state + rkf78 stage vectors (13 stages + 5 work vectors), 202 beads
  CHECK(stored <= e.memory_bytes);
  CHECK(stored >= e.memory_bytes / 4);

  const fs::path dir = fs::temp_directory_path() / ("lrchain-estimate-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  jobs::write_record(dir, r.record);
  double written = 0;
  for (const auto& f : fs::directory_iterator(dir)) written += double(fs::file_size(f.path()));
  fs::remove_all(dir);
  const double data_estimate = e.output_bytes - 2e6;  // without the allowance for summary and figures
  CHECK(written <= data_estimate);
  CHECK(written >= data_estimate / 4);
}

TEST_CASE("locate_blow_up maps the first non-finite entry to a site label and a field") {
  IntegrationStats st;
  CHECK_FALSE(locate_blow_up(st, 10, -5).has_value());
  st.blew_up = true;
  st.t_reached = 12.5;
  st.blow_up_index = 2 * 10 + 3;  // third block (du/dt), fourth site
  const auto b = locate_blow_up(st, 10, -5);
  REQUIRE(b.has_value());
  CHECK(b->site == -2);
  CHECK(b->field == "du/dt");
  CHECK(b->t == 12.5);
  CHECK(b->message().find("t = 12.5") != std::string::npos);
}

TEST_CASE("parse_memory_size reads binary units and refuses anything else") {
  CHECK(parse_memory_size("2G", "max-memory") == 2.0 * 1024 * 1024 * 1024);
  CHECK(parse_memory_size("500M", "max-memory") == 500.0 * 1024 * 1024);
  CHECK(parse_memory_size("1.5T", "max-memory") == 1.5 * 1024.0 * 1024 * 1024 * 1024);
  CHECK(parse_memory_size("2GiB", "max-memory") == 2.0 * 1024 * 1024 * 1024);
  CHECK(parse_memory_size("4096k", "max-memory") == 4096.0 * 1024);
  for (const char* bad : {"", "G", "lots", "-1G", "nan", "inf", "1e400G", "64k", "2X", "2GG"})
    CHECK_THROWS_AS(parse_memory_size(bad, "max-memory"), InvalidParameter);
  CHECK(format_bytes(48e9) == "48 GB");
  CHECK(format_bytes(1.5e6) == "1.5 MB");
}

TEST_CASE("a bright run's lattice size is refused in sites = 2N + 1, also where 2N + 1 overflows") {
  BrightRunConfig b = small_bright();
  b.N = 1;  // 3 sites, below the 5 of bright_sites
  try {
    validate(b);
    FAIL("3 sites accepted");
  } catch (const InvalidParameter& e) {
    CHECK(std::string(e.what()).find("must be an odd integer in [5, 2000000000000001]") != std::string::npos);
    CHECK(std::string(e.what()).find("(got 3)") != std::string::npos);
  }
  b.N = std::numeric_limits<Index>::max();  // 2N + 1 does not fit: the message gives N itself
  try {
    validate(b);
    FAIL("N = max accepted");
  } catch (const InvalidParameter& e) {
    CHECK(e.parameter() == "sites");
    CHECK(std::string(e.what()).find("(got N = 9223372036854775807)") != std::string::npos);
  }
}

TEST_CASE("the drive's switch-off time is a finite time >= 0 from options and Python as from a config") {
  DriveRunConfig d;
  d.t_m = 0;  // chi(t) switched off from the start: allowed (the config key's range is >= 0)
  CHECK(refused_parameter([&] { validate(d); }) != "switch_off_time");
  d.t_m = -1;
  CHECK(refused_parameter([&] { validate(d); }) == "switch_off_time");
}
