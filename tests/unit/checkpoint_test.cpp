// Checkpoint format 3 (lrchain/jobs/checkpoint/checkpoint_file.hpp) and the runs' checkpoint store
// (lrchain/sim/checkpoint_store.hpp, as files: jobs::with_checkpoint_files): round trip, every kind of damaged file refused
// with an InputError naming it, a changed parameter refused naming it, and restarts equal to the
// uninterrupted run bit for bit (expected value: the uninterrupted run itself, compared exactly).
#include <doctest/doctest.h>

#include <unistd.h>

#include <atomic>
#include <boost/crc.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <string>

#include "lrchain/errors.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/sha256.hpp"
#include "lrchain/jobs/checkpoint/checkpoint_file.hpp"
#include "lrchain/jobs/checkpoint/checkpoint_files.hpp"
#include "lrchain/sim/drive_run.hpp"
#include "lrchain/sim/modulated_run.hpp"
#include "lrchain/jobs/output_files.hpp"

using namespace lrchain;
using namespace lrchain::sim;
using namespace lrchain::jobs;
namespace fs = std::filesystem;

namespace {

// The runs with their checkpoints as files, as the simulate job runs them.
BrightRunResult run_bright_files(const BrightRunConfig& c, const RunControl& control = {}) {
  return run_resonant_chain_bright(c, with_checkpoint_files(control, c));
}
DriveRunResult run_drive_files(const DriveRunConfig& c, const RunControl& control = {}) {
  return run_drive(c, with_checkpoint_files(control, c));
}
ModulatedRunResult run_modulated_files(const ModulatedRunConfig& c, const RunControl& control = {}) {
  return run_modulated(c, with_checkpoint_files(control, c));
}

fs::path scratch_dir(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("lrchain-checkpoint-test-" + name + "-" +
                                                  std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& f) {
  std::ifstream in(f, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void spit(const fs::path& f, const std::string& bytes) {
  std::ofstream out(f, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), std::streamsize(bytes.size()));
}

// Replaces the trailing CRC-32 so that a deliberately edited file passes the checksum and reaches
// the later checks.
std::string with_valid_crc(std::string bytes) {
  boost::crc_32_type crc;
  crc.process_bytes(bytes.data(), bytes.size() - 4);
  const std::uint32_t v = crc.checksum();
  std::memcpy(bytes.data() + bytes.size() - 4, &v, 4);
  return bytes;
}

Checkpoint sample_checkpoint(double t, double first_state_value) {
  TrajectoryIdentity id;
  id.add("run", "test");
  id.add("rho", 1.0 / 3.0);
  id.add("N", 3L);
  Checkpoint c;
  c.identity = id.text();
  c.t = t;
  c.next_step = 0.0123456789;
  c.steps = 17;
  c.rhs_evaluations = 170;
  c.accumulators = {{"max_Ex", 0.1 + 0.2}, {"first", 1.0}};
  c.state = {first_state_value, -2.5, std::nextafter(1.0, 2.0), 1e-300};
  return c;
}

RunRecord sample_record() {
  RunRecord r;
  r.series.names = {"t", "a"};
  r.series.data = {0, 1.0 / 7, 1, 2.0 / 7};
  SpaceTime f;
  f.quantity = "energy_density";
  f.first_label = -3;
  f.sites = 2;
  f.times = {0, 1};
  f.values = {1.5f, 2.5f, 3.5f, 4.5f};
  r.fields.push_back(f);
  Snapshot s;
  s.t = 1;
  s.tag = "t1";
  s.names = {"n", "x"};
  s.data = {-1, 0.25, 0, 0.5};
  r.snapshots.push_back(s);
  return r;
}

// The state-count field follows magic (8), version (4), identity (8 + len), identity hash (SHA-256,
// 32), progress (8 + len).
std::size_t state_count_offset(const std::string& bytes) {
  std::uint64_t len = 0;
  std::memcpy(&len, bytes.data() + 12, 8);
  std::size_t pos = 12 + 8 + std::size_t(len) + 32;
  std::memcpy(&len, bytes.data() + pos, 8);
  return pos + 8 + std::size_t(len);
}

void check_refused(const fs::path& f, const std::string& what) {
  try {
    read_checkpoint(f);
    FAIL("accepted a checkpoint with " << what);
  } catch (const InputError& e) {
    const std::string m = e.what();
    CHECK_MESSAGE(m.find(f.string()) != std::string::npos, m);
    CHECK_MESSAGE(m.find('\n') == std::string::npos, m);
  }
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}
bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// Everything two runs observed, compared bit for bit.
void check_same_record(const RunRecord& a, const RunRecord& b) {
  CHECK(a.series.names == b.series.names);
  CHECK(a.series.rows() == b.series.rows());
  CHECK(same_bits(a.series.data, b.series.data));
  REQUIRE(a.fields.size() == b.fields.size());
  for (std::size_t k = 0; k < a.fields.size(); ++k) {
    CHECK(same_bits(a.fields[k].times, b.fields[k].times));
    CHECK(same_bits(a.fields[k].values, b.fields[k].values));
  }
  REQUIRE(a.snapshots.size() == b.snapshots.size());
  for (std::size_t k = 0; k < a.snapshots.size(); ++k) CHECK(same_bits(a.snapshots[k].data, b.snapshots[k].data));
}

BrightRunConfig small_bright(StepperKind stepper) {
  BrightRunConfig c;
  c.branch = Branch::optical;
  c.theta = M_PI / 2;
  c.N = 40;
  c.periods = 4;
  c.sample_every = 0.25;
  c.spacetime_every = 0.5;
  c.snapshot_periods = {0, 1.5, 4};
  c.centre_window = 10;
  c.integrator.stepper = stepper;
  c.integrator.abs_tol = c.integrator.rel_tol = 1e-10;
  c.integrator.dt = 0.05;
  return c;
}

}  // namespace

TEST_CASE("checkpoint: write then read gives back every value bit for bit") {
  const fs::path dir = scratch_dir("roundtrip");
  const Checkpoint c = sample_checkpoint(2.75, 0.1);
  const RunRecord rec = sample_record();
  write_checkpoint(dir / "c.bin", c, rec);
  const Checkpoint r = read_checkpoint(dir / "c.bin");
  CHECK(r.identity == c.identity);
  CHECK(r.identity.rfind("lrchain_version = ", 0) == 0);
  CHECK(r.identity.find("rho = 0.3333333333333333\n") != std::string::npos);
  CHECK(r.t == c.t);
  CHECK(r.next_step == c.next_step);
  CHECK(r.steps == 17);
  CHECK(r.rhs_evaluations == 170);
  CHECK(r.accumulator(dir / "c.bin", "max_Ex") == 0.1 + 0.2);
  CHECK_THROWS_AS(r.accumulator(dir / "c.bin", "nope"), InputError);
  CHECK(same_bits(r.state, c.state));
  check_same_record(r.record, rec);
  // no temporary file is left, and the temporary name is this process's own
  for (const auto& e : fs::directory_iterator(dir)) CHECK(e.path().filename() == "c.bin");
  CHECK(temporary_name(dir / "c.bin").filename().string() ==
        ".c.bin.tmp." + std::to_string(::getpid()));
  fs::remove_all(dir);
}

TEST_CASE("checkpoint: truncated, corrupted, wrong-version, huge-size, NaN and negative-time files are refused") {
  const fs::path dir = scratch_dir("damaged");
  write_checkpoint(dir / "good.bin", sample_checkpoint(1.0, 0.5), sample_record());
  const std::string good = slurp(dir / "good.bin");
  const fs::path f = dir / "bad.bin";

  for (std::size_t keep : {std::size_t(0), std::size_t(5), std::size_t(12), std::size_t(40), good.size() / 2,
                           good.size() - 1}) {
    spit(f, good.substr(0, keep));
    check_refused(f, "a truncation to " + std::to_string(keep) + " bytes");
  }
  for (std::size_t at : {std::size_t(3), std::size_t(30), good.size() / 2, good.size() - 2}) {
    std::string b = good;
    b[at] = char(b[at] ^ 0x10);
    spit(f, b);
    check_refused(f, "a flipped bit at byte " + std::to_string(at));
  }
  {
    std::string b = good;
    const std::uint32_t v4 = 4;
    std::memcpy(b.data() + 8, &v4, 4);
    spit(f, with_valid_crc(b));
    check_refused(f, "format version 4");
  }
  {  // a state size of 2^60 doubles with a valid CRC: refused before any allocation
    std::string b = good;
    const std::uint64_t huge = 1ull << 60;
    std::memcpy(b.data() + state_count_offset(b), &huge, 8);
    spit(f, with_valid_crc(b));
    check_refused(f, "a 2^60-entry state");
  }
  write_checkpoint(f, sample_checkpoint(1.0, std::numeric_limits<double>::quiet_NaN()), sample_record());
  check_refused(f, "a NaN in the state");
  write_checkpoint(f, sample_checkpoint(-1.0, 0.5), sample_record());
  check_refused(f, "a negative time");
  write_checkpoint(f, sample_checkpoint(std::numeric_limits<double>::infinity(), 0.5), sample_record());
  check_refused(f, "an infinite time");
  check_refused(dir / "missing.bin", "no file at all");
  fs::remove_all(dir);
}

TEST_CASE("checkpoint: a mismatch names an item as the user sets it, its recorded key unchanged") {
  const fs::path file = "c.bin";
  const auto mismatch = [&](const TrajectoryIdentity& written, const TrajectoryIdentity& run) {
    Checkpoint c;
    c.identity = written.text();
    try {
      check_same_trajectory(file, c, run);
    } catch (const InvalidParameter& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const auto half_width_as_sites = [](long n) { return 2 * n + 1; };
  TrajectoryIdentity a, b;
  a.add("N", 500L, {"sites", half_width_as_sites});
  b.add("N", 400L, {"sites", half_width_as_sites});
  // The file records the old key: a checkpoint written before the key was renamed still matches.
  CHECK(a.text().find("\nN = 500\n") != std::string::npos);
  CHECK(mismatch(a, a) == "accepted");
  CHECK(mismatch(a, b) == "invalid restart: checkpoint 'c.bin' was written with sites = 1001, this run has sites = 801");
  TrajectoryIdentity d1, d2;
  d1.add("t_m", 700.0, {"switch_off_time"});
  d2.add("t_m", 650.5, {"switch_off_time"});
  CHECK(mismatch(d1, d2) ==
        "invalid restart: checkpoint 'c.bin' was written with switch_off_time = 700, this run has switch_off_time = 650.5");
  // An item added without ShownAs keeps its key; a recorded value that is not a long is shown as is.
  TrajectoryIdentity p1, p2;
  p1.add("rho", 0.5);
  p2.add("rho", 0.25);
  CHECK(mismatch(p1, p2) == "invalid restart: checkpoint 'c.bin' was written with rho = 0.5, this run has rho = 0.25");
  CHECK(b.shown("N", "x1") == "N = x1");
}

TEST_CASE("checkpoint: a restart with a changed parameter or stepper is refused, naming the item") {
  const fs::path dir = scratch_dir("identity");
  BrightRunConfig c = small_bright(StepperKind::rkf78);
  c.periods = 1;
  c.checkpoint_file = (dir / "a.bin").string();
  c.checkpoint_at_end = true;
  run_bright_files(c);
  REQUIRE(fs::exists(dir / "a.bin"));
  c.checkpoint_file.clear();
  c.restart_file = (dir / "a.bin").string();
  c.periods = 2;

  auto expect = [&](BrightRunConfig changed, const std::string& text) {
    try {
      run_bright_files(changed);
      FAIL("restart accepted with " << text);
    } catch (const InvalidParameter& e) {
      CHECK_MESSAGE(std::string(e.what()).find(text) != std::string::npos, e.what());
      CHECK(std::string(e.what()).find((dir / "a.bin").string()) != std::string::npos);
    }
  };
  BrightRunConfig x = c;
  x.params.rho = 0.5;
  expect(x, "was written with rho = 0.3333333333333333, this run has rho = 0.5");
  x = c;
  x.params.kappa = 2;
  expect(x, "kappa = 1, this run has kappa = 2");
  x = c;
  x.integrator.stepper = StepperKind::dopri5;
  expect(x, "stepper = rkf78, this run has stepper = dopri5");
  x = c;
  x.integrator.rel_tol = 1e-9;
  expect(x, "rel_tol");
  x = c;
  x.N = 41;  // recorded as the half-width N; named as the user sets it, sites = 2N + 1
  expect(x, "was written with sites = 81, this run has sites = 83");
  x = c;
  x.theta = 1.5;
  expect(x, "theta");
  x = c;
  x.periods = 1;  // the checkpoint is at the end of this shorter run already
  expect(x, "nothing left to integrate");
  // a drive run cannot continue a bright run's checkpoint
  DriveRunConfig d;
  d.beads = 20;
  d.t_end = 5;
  d.restart_file = (dir / "a.bin").string();
  CHECK_THROWS_AS(run_drive_files(d), InvalidParameter);
  // the unchanged run continues
  CHECK(run_bright_files(c).summary.t_start > 0);
  fs::remove_all(dir);
}

TEST_CASE("a run naming a checkpoint or restart file without a store in RunControl is refused: sim writes no files") {
  const fs::path dir = scratch_dir("no-store");
  BrightRunConfig c = small_bright(StepperKind::rkf78);
  c.checkpoint_file = (dir / "c.bin").string();
  CHECK_THROWS_WITH_AS(run_resonant_chain_bright(c), doctest::Contains("needs a checkpoint store"), InvalidParameter);
  CHECK(!fs::exists(c.checkpoint_file));
  c.checkpoint_file.clear();
  c.restart_file = (dir / "c.bin").string();
  CHECK_THROWS_WITH_AS(run_resonant_chain_bright(c), doctest::Contains("needs a checkpoint store"), InvalidParameter);
  fs::remove_all(dir);
}

TEST_CASE("a checkpoint store in memory: the run saves through it and a restart from it equals the uninterrupted run") {
  // Expected value: the uninterrupted run itself, compared bit for bit (the same step sequence).
  // (no snapshots: a run that writes no checkpoint file to continue may not name times beyond its end)
  const auto without_snapshots = [] {
    BrightRunConfig c = small_bright(StepperKind::rkf78);
    c.snapshot_periods.clear();
    return c;
  };
  const auto uninterrupted = run_resonant_chain_bright(without_snapshots());
  std::optional<SavedRun> saved;
  std::string saved_identity;
  RunControl control;
  control.checkpoints.save = [&](const TrajectoryIdentity& id, const RunProgress& p, const State& s, const RunRecord& r) {
    saved = SavedRun{p, s, r};
    saved_identity = id.text();
  };
  BrightRunConfig first = without_snapshots();
  first.periods = 2;
  first.checkpoint_at_end = true;
  const auto head = run_resonant_chain_bright(first, control);
  REQUIRE(saved);
  CHECK(head.summary.checkpoints_written == 1);
  CHECK(saved->progress.t == head.summary.t_end);
  RunControl resume;
  std::string asked_kind;
  resume.checkpoints.load = [&](const RestartRequest& r) {
    asked_kind = r.kind;
    CHECK(r.identity.text() == saved_identity);
    CHECK(r.state_size == saved->state.size());
    return *saved;
  };
  const auto restarted = run_resonant_chain_bright(without_snapshots(), resume);
  CHECK(asked_kind == "bright");
  CHECK(restarted.summary.t_start == saved->progress.t);
  check_same_record(restarted.record, uninterrupted.record);
  CHECK(restarted.summary.max_Ex == uninterrupted.summary.max_Ex);
  CHECK(restarted.summary.final_Ey == uninterrupted.summary.final_Ey);
}

TEST_CASE("restart equals the uninterrupted run to the last bit: bright, to t1 then to t2") {
  // rkf78 and the fixed-step steppers land on every observation time; a checkpoint there stores
  // the step size carried to the next interval, so the continued step sequence is the same.
  for (StepperKind stepper : {StepperKind::rkf78, StepperKind::symplectic, StepperKind::srkn11b}) {
    CAPTURE(to_string(stepper));
    const fs::path dir = scratch_dir("bright-t1t2");
    BrightRunConfig full = small_bright(stepper);
    full.checkpoint_file = (dir / "full.bin").string();
    full.checkpoint_at_end = true;
    const auto uninterrupted = run_bright_files(full);
    REQUIRE(!uninterrupted.summary.blew_up);

    BrightRunConfig first = small_bright(stepper);
    first.periods = 2;
    first.checkpoint_file = (dir / "t1.bin").string();
    first.checkpoint_at_end = true;
    run_bright_files(first);
    BrightRunConfig second = small_bright(stepper);
    second.restart_file = (dir / "t1.bin").string();
    second.checkpoint_file = (dir / "t2.bin").string();
    second.checkpoint_at_end = true;
    const auto restarted = run_bright_files(second);

    check_same_record(restarted.record, uninterrupted.record);
    CHECK(same_bits(read_checkpoint(dir / "t2.bin").state, read_checkpoint(dir / "full.bin").state));
    const auto &a = restarted.summary, &b = uninterrupted.summary;
    CHECK(a.max_Ex == b.max_Ex);
    CHECK(a.max_Ey == b.max_Ey);
    CHECK(a.final_Ex == b.final_Ex);
    CHECK(a.energy0 == b.energy0);
    CHECK(a.max_energy_drift == b.max_energy_drift);
    CHECK(a.centre_speed == b.centre_speed);
    CHECK(a.t_end == b.t_end);
    CHECK(a.stats.steps == b.stats.steps);
    CHECK(a.t_start > 0);
    fs::remove_all(dir);
  }
}

TEST_CASE("restart after an interrupt equals the uninterrupted run to the last bit, every stepper") {
  // The stop flag is raised from the progress callback (as the CLI's signal handler would): the run
  // stops at the next step boundary and writes its checkpoint there. For dopri5 (dense output) the
  // boundary is the end of the stepper's own step, after the observations inside it.
  for (StepperKind stepper : {StepperKind::rkf78, StepperKind::dopri5, StepperKind::symplectic,
                              StepperKind::srkn14a, StepperKind::ss17}) {
    CAPTURE(to_string(stepper));
    const fs::path dir = scratch_dir("interrupt");
    const auto uninterrupted = run_bright_files(small_bright(stepper));

    std::atomic<bool> stop{false};
    RunControl control;
    control.stop = &stop;
    control.progress = [&stop](double f) {
      if (f > 0.4) stop.store(true);
    };
    BrightRunConfig c = small_bright(stepper);
    c.checkpoint_file = (dir / "i.bin").string();
    const auto interrupted = run_bright_files(c, control);
    REQUIRE(interrupted.summary.interrupted);
    CHECK(interrupted.summary.t_end < uninterrupted.summary.t_end);
    CHECK(interrupted.summary.checkpoints_written == 1);
    // the interrupted record is the first part of the full one
    const auto& part = interrupted.record.series.data;
    REQUIRE(part.size() < uninterrupted.record.series.data.size());
    CHECK(std::memcmp(part.data(), uninterrupted.record.series.data.data(), part.size() * sizeof(double)) == 0);

    c.restart_file = c.checkpoint_file;
    c.checkpoint_file.clear();
    const auto restarted = run_bright_files(c);
    CHECK(!restarted.summary.interrupted);
    check_same_record(restarted.record, uninterrupted.record);
    CHECK(restarted.summary.max_Ex == uninterrupted.summary.max_Ex);
    CHECK(restarted.summary.centre_speed == uninterrupted.summary.centre_speed);
    CHECK(restarted.summary.stats.steps == uninterrupted.summary.stats.steps);
    fs::remove_all(dir);
  }
}

TEST_CASE("restart equals the uninterrupted run to the last bit: drive (rkf78) and modulated (symplectic)") {
  const fs::path dir = scratch_dir("drive-modulated");
  {
    DriveRunConfig c;
    c.beads = 30;
    c.t_end = 30;
    c.t_m = 20;
    c.ramp_rate = 0.3;
    c.snapshot_times = {15, 30};
    c.front_fit_start = 2;
    c.front_fit_end = 25;
    const auto full = run_drive_files(c);
    c.t_end = 12;
    c.checkpoint_file = (dir / "d.bin").string();
    c.checkpoint_at_end = true;
    run_drive_files(c);
    c.t_end = 30;
    c.restart_file = c.checkpoint_file;
    c.checkpoint_file.clear();
    const auto restarted = run_drive_files(c);
    check_same_record(restarted.record, full.record);
    CHECK(restarted.summary.front_speed == full.summary.front_speed);
    CHECK(restarted.summary.max_participation == full.summary.max_participation);
    CHECK(restarted.summary.final_peaks == full.summary.final_peaks);
  }
  {
    ModulatedRunConfig c;
    c.N = 32;
    c.theta_waves = 20;
    c.t_end = 60;
    c.sample_every = 2;
    c.snapshot_times = {0, 30};
    c.speed_fit_start = 10;
    c.speed_fit_end = 50;
    c.checkpoint_every = 0;
    const auto full = run_modulated_files(c);
    c.checkpoint_every = 10;
    c.t_end = 20;
    c.checkpoint_file = (dir / "m.bin").string();
    const auto first = run_modulated_files(c);
    CHECK(first.summary.checkpoints_written == 2);  // t = 10 and the end, t = 20
    c.t_end = 60;
    c.restart_file = c.checkpoint_file;
    c.checkpoint_file.clear();
    const auto restarted = run_modulated_files(c);
    check_same_record(restarted.record, full.record);
    CHECK(restarted.summary.dark_speed == full.summary.dark_speed);
    CHECK(restarted.summary.max_energy_drift == full.summary.max_energy_drift);
    CHECK(restarted.summary.t_start == 20);
  }
  fs::remove_all(dir);
}

TEST_CASE("checkpoint identity and initial-state hashes are SHA-256, and a format-2 (FNV-1a) file is refused saying so") {
  const fs::path dir = scratch_dir("sha256");
  const Checkpoint c = sample_checkpoint(1.0, 0.5);
  write_checkpoint(dir / "c.bin", c, sample_record());
  const std::string bytes = slurp(dir / "c.bin");
  // The identity's length at byte 12, its text, then its 32-byte SHA-256 (was an 8-byte FNV-1a).
  std::uint64_t len = 0;
  std::memcpy(&len, bytes.data() + 12, 8);
  REQUIRE(bytes.substr(20, len) == c.identity);
  const lrchain::Sha256Digest digest = lrchain::sha256(c.identity);
  CHECK(std::memcmp(bytes.data() + 20 + len, digest.data(), digest.size()) == 0);
  // A changed identity byte with a valid CRC is caught by the SHA-256.
  std::string forged = bytes;
  forged[20] = char(forged[20] ^ 0x01);
  spit(dir / "forged.bin", with_valid_crc(forged));
  check_refused(dir / "forged.bin", "an identity that does not match its SHA-256");
  // The state hash item: "sha256:" and 64 hexadecimal digits of the state's bytes.
  TrajectoryIdentity id;
  const State s{1.0, 2.0};
  id.add_state_hash("initial_state", s);
  CHECK(id.items().back().second ==
        "sha256:" + lrchain::sha256_hex(std::string_view(reinterpret_cast<const char*>(s.data()), 2 * sizeof(double))));
  // Format 2 (lrchain 0.1): refused with the reason, not read with a weaker hash.
  std::string old = bytes;
  const std::uint32_t v2 = 2;
  std::memcpy(old.data() + 8, &v2, 4);
  spit(dir / "v2.bin", with_valid_crc(old));
  CHECK_THROWS_WITH_AS(read_checkpoint(dir / "v2.bin"), doctest::Contains("format version 2, written by lrchain 0.1"),
                       InputError);
  fs::remove_all(dir);
}
