// Times of a lattice run beyond its end (sampling_checks.cpp through bright/drive/modulated
// validate): snapshot times, checkpoint-every, the drive's t_m and fit window, the modulated run's
// fit window may lie beyond t_end (for a continuation with --restart), but not beyond the longest
// run of the same configuration whose samples fit in memory; the refusal names the option and the
// largest time allowed, and that time is itself accepted.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>

#include "lrchain/errors.hpp"
#include "lrchain/sim/resonant_chain_bright_run.hpp"
#include "lrchain/sim/drive_run.hpp"
#include "lrchain/sim/modulated_run.hpp"
#include "short_runs.hpp"

using namespace lrchain;
using namespace lrchain::sim;
using lrchain::test::short_drive;

namespace {

// The InvalidParameter that f throws: its parameter and message ("", "" if none is thrown).
template <class F>
std::pair<std::string, std::string> refusal(F&& f) {
  try {
    f();
  } catch (const InvalidParameter& e) {
    return {e.parameter(), e.what()};
  }
  return {"", ""};
}

// The largest time a refusal allows: the number after `marker` ("at most ", "[0, ").
double largest_allowed(const std::string& message, const std::string& marker) {
  const auto at = message.find(marker);
  REQUIRE_MESSAGE(at != std::string::npos, message);
  return std::strtod(message.c_str() + at + marker.size(), nullptr);
}

}  // namespace

TEST_CASE("drive: the switch-off time and the fit window beyond t_end are accepted up to the reach, refused past it") {
  DriveRunConfig d = short_drive();
  CHECK_NOTHROW(validate(d));
  // The paper's window [100, 700] and t_m = 700 on a run of 60: beyond the end, well within reach
  // (the front speed is null then; the window applies to a continuation).
  d.front_fit_start = 100;
  d.front_fit_end = 700;
  d.t_m = 700;
  CHECK_NOTHROW(validate(d));
  for (const char* option : {"switch_off_time", "front_fit_end"}) {
    DriveRunConfig huge = short_drive();
    (std::string(option) == "switch_off_time" ? huge.t_m : huge.front_fit_end) = 1e308;
    const auto [parameter, message] = refusal([&] { validate(huge); });
    CHECK(parameter == option);
    // The largest time the message gives is accepted, 1 % more is not (the bisection's
    // tolerance is 1e-4 relative).
    const double reach = largest_allowed(message, "at most ");
    CHECK(reach > d.t_end);
    DriveRunConfig edge = short_drive();
    (std::string(option) == "switch_off_time" ? edge.t_m : edge.front_fit_end) = reach;
    CHECK_NOTHROW(validate(edge));
    (std::string(option) == "switch_off_time" ? edge.t_m : edge.front_fit_end) = 1.01 * reach;
    CHECK(refusal([&] { validate(edge); }).first == option);
  }
}

TEST_CASE("checkpoint-every beyond the run is accepted up to the reach — 1e308 is refused with the range") {
  DriveRunConfig d = short_drive();
  d.checkpoint_every = 100;  // the first periodic checkpoint in a continuation
  CHECK_NOTHROW(validate(d));
  d.checkpoint_every = 1e308;
  const auto [parameter, message] = refusal([&] { validate(d); });
  CHECK(parameter == "checkpoint_every");
  CHECK(message.find("must be 0 (none) or in [sample-every, ") != std::string::npos);
  BrightRunConfig b;
  b.N = 50;
  b.periods = 1;
  b.sample_every = 0.25;
  b.spacetime_every = 0.5;
  b.snapshot_periods = {0, 1};
  b.checkpoint_every = 1e300 * 3.141592653589793;
  CHECK(refusal([&] { validate(b); }).first == "checkpoint_every");
}

TEST_CASE("snapshots beyond the end of a continued run are refused past the reach") {
  ModulatedRunConfig m;
  m.N = 21;
  m.theta_waves = 13;
  m.t_end = 2;
  m.sample_every = 1;
  m.snapshot_times = {0, 1e308};
  m.speed_fit_start = 0;
  m.speed_fit_end = 2;
  m.checkpoint_every = 1;
  m.checkpoint_file = "checkpoint.bin";  // continued later: snapshots may lie beyond t_end
  m.max_memory = 64.0 * (1 << 20);
  const auto [parameter, message] = refusal([&] { validate(m); });
  CHECK(parameter == "snapshots");
  const double reach = largest_allowed(message, "must be in [0, ");
  CHECK(reach > m.t_end);
  m.snapshot_times = {0, reach};
  CHECK_NOTHROW(validate(m));
  m.speed_fit_end = 1e308;
  m.snapshot_times = {0, 1};
  CHECK(refusal([&] { validate(m); }).first == "speed_fit_end");
}
