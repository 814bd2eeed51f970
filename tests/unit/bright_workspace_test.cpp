// A sweep thread's BrightWorkspace (resonant_chain_bright_run.hpp) is reused from point to point: runs of different
// sizes, parameters and ends, one after another in the same workspace, give the same numbers bit for
// bit as each run on its own (run_resonant_chain_bright without a workspace: the expected values).
#include <doctest/doctest.h>

#include <cstring>
#include <vector>

#include "lrchain/sim/resonant_chain_bright_run.hpp"

using namespace lrchain;
using namespace lrchain::sim;

namespace {

BrightRunConfig small_run(long N, double rho, bool ansatz_ends, double n0) {
  BrightRunConfig c;
  c.params.rho = rho;
  c.theta = 1.5707963267948966;
  c.N = N;
  c.n0 = n0;
  c.periods = 2;
  c.snapshot_periods = {0, 2};
  c.ansatz_ends = ansatz_ends;
  c.integrator = {.stepper = StepperKind::rkf78, .abs_tol = 1e-10, .rel_tol = 1e-10};
  return c;
}

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

}  // namespace

TEST_CASE("bright workspace: runs of different N, rho and ends in one workspace equal their own runs bit for bit" *
          doctest::test_suite("fast")) {
  // Grows (40 -> 60), shrinks (60 -> 30), changes rho (lattice rebuilt), switches to prescribed ends
  // and back, and repeats a run with only n0 changed (lattice kept).
  const std::vector<BrightRunConfig> runs = {small_run(40, 1.0 / 3, false, 0), small_run(60, 1.0 / 3, false, 0),
                                             small_run(30, 1.0 / 3, false, 0), small_run(30, 0.5, false, 0),
                                             small_run(30, 0.5, true, 0),      small_run(30, 0.5, false, 0.5)};
  BrightWorkspace workspace;
  for (const BrightRunConfig& c : runs) {
    CAPTURE(c.N);
    CAPTURE(c.ansatz_ends);
    const BrightRunResult alone = run_resonant_chain_bright(c);
    const BrightRunSummary s = run_resonant_chain_bright(c, workspace);
    CHECK(same_bits(s.max_Ex, alone.summary.max_Ex));
    CHECK(same_bits(s.max_Ey, alone.summary.max_Ey));
    CHECK(same_bits(s.centre_speed, alone.summary.centre_speed));
    CHECK(same_bits(s.max_energy_drift, alone.summary.max_energy_drift));
    CHECK(s.stats.steps == alone.summary.stats.steps);
    CHECK(same_bits(workspace.record.series.data, alone.record.series.data));
    REQUIRE(workspace.record.fields.size() == 1);
    CHECK(workspace.record.fields[0].values == alone.record.fields[0].values);
    CHECK(workspace.record.fields[0].sites == std::size_t(2 * c.N + 2));
    REQUIRE(workspace.record.snapshots.size() == alone.record.snapshots.size());
    for (std::size_t k = 0; k < alone.record.snapshots.size(); ++k)
      CHECK(same_bits(workspace.record.snapshots[k].data, alone.record.snapshots[k].data));
    CHECK(alone.summary.max_Ex > 0);  // a run that measured something
  }
}
