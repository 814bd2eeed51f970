// The stop flag (SIGINT/SIGTERM) is polled inside integrate_observed's step loops, not only at
// observations: a run with one long interval between observations stops within a step of the flag
// (before, it ran on to the next observation: rkf78 with --abs-tol 1e-300 --rel-tol 0 ignored the
// first SIGINT for more than 30 s). rkf78 and dopri5 hand the step boundary they are at to the
// hook, and a restart from there gives the uninterrupted run's bits; the fixed-step steppers go
// back to their last observation. Tolerances double precision cannot meet are exit 2.
#include <doctest/doctest.h>

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "../support/run_lrchain.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/sim/displacement_lattice.hpp"
#include "lrchain/sim/integrator.hpp"

using namespace lrchain;
using namespace lrchain::sim;
namespace fs = std::filesystem;

namespace {

// A chain that raises `stop` at its `raise_at`-th force evaluation: a deterministic stand-in for a
// signal arriving between two observations.
struct RaisingChain {
  const DisplacementLattice* chain;
  std::atomic<bool>* stop;
  long raise_at;
  mutable long calls = 0;
  void raise() const {
    if (++calls == raise_at) stop->store(true);
  }
  void operator()(const State& s, State& ds, double t) const {
    raise();
    (*chain)(s, ds, t);
  }
  void acceleration(const double* q, double* a, double t) const {
    raise();
    chain->acceleration(q, a, t);
  }
  bool autonomous() const { return true; }
};

Params resonant() {
  Params p;
  p.rho = 1.0 / 3;
  return p;
}

State initial_state(const DisplacementLattice& chain) {
  State s(chain.layout().size(), 0.0);
  s[10] = 0.01;
  s[11] = -0.005;
  return s;
}

IntegratorOptions options(StepperKind k) {
  IntegratorOptions o;
  o.stepper = k;
  o.dt = 0.01;
  return o;
}

struct Stop {
  State state;
  double t = -1, next_step = 0;
  Index steps = 0;
  int calls = 0;
};

}  // namespace

TEST_CASE("the stop flag ends a run between two observations, within a step, for every stepper") {
  const DisplacementLattice chain(resonant(), 20);
  // One interval of 2000 time units: some 10^5 steps; the flag goes up at the 300th force evaluation.
  const std::vector<double> times{0.0, 2000.0};
  for (StepperKind k : {StepperKind::rkf78, StepperKind::dopri5, StepperKind::symplectic, StepperKind::srkn11b,
                        StepperKind::srkn14a, StepperKind::ss17}) {
    CAPTURE(to_string(k));
    std::atomic<bool> stop{false};
    const RaisingChain raising{&chain, &stop, 300};
    State s = initial_state(chain);
    const State s0 = s;
    Stop seen;
    const StepBoundaryHook hook = [&](const State& x, double t, double next, const IntegrationStats& work) {
      if (!stop.load()) return true;
      seen = {x, t, next, work.steps, seen.calls + 1};
      return false;  // as the runs' hooks do on an interrupt: checkpoint here, then stop
    };
    const IntegrationStats st = integrate_observed(raising, s, times, [](const State&, double) { return true; },
                                                   options(k), hook, 0, &stop);
    CHECK(st.stopped);
    CHECK(st.t_reached == 0.0);     // the observation at 2000 was never made
    CHECK(raising.calls < 400);     // it stopped within a step of the flag (rkf78: 13 evaluations a step)
    REQUIRE(seen.calls == 1);
    if (is_symplectic(k)) {
      // Back at the last observation: its state and work, untouched by the steps after it.
      CHECK(seen.t == 0.0);
      CHECK(seen.state == s0);
      CHECK(seen.steps == 0);
      CHECK(st.rhs_evaluations == 0);
    } else {
      CHECK(seen.t > 0.0);
      CHECK(seen.t < 2000.0);
      CHECK(seen.steps > 0);
      if (k == StepperKind::rkf78) CHECK(seen.state == s);  // the caller's state is the one handed to the hook
    }
  }
}

TEST_CASE("rkf78 and dopri5: a restart from the step boundary where the flag stopped them gives the uninterrupted bits") {
  const DisplacementLattice chain(resonant(), 20);
  const std::vector<double> times{0.0, 3.0, 7.5, 40.0};
  for (StepperKind k : {StepperKind::rkf78, StepperKind::dopri5}) {
    CAPTURE(to_string(k));
    std::vector<State> full_observed;
    State full = initial_state(chain);
    integrate_observed(chain, full, times, [&](const State& x, double) {
      full_observed.push_back(x);
      return true;
    }, options(k));

    std::atomic<bool> stop{false};
    const RaisingChain raising{&chain, &stop, 700};  // between two observations
    State s = initial_state(chain);
    Stop seen;
    const StepBoundaryHook hook = [&](const State& x, double t, double next, const IntegrationStats& work) {
      if (!stop.load()) return true;
      seen = {x, t, next, work.steps, 1};
      return false;
    };
    std::vector<State> observed;
    integrate_observed(raising, s, times, [&](const State& x, double) {
      observed.push_back(x);
      return true;
    }, options(k), hook, 0, &stop);
    REQUIRE(seen.calls == 1);
    REQUIRE(seen.t > 0.0);
    REQUIRE(seen.t < 40.0);
    REQUIRE(std::find(times.begin(), times.end(), seen.t) == times.end());  // inside an interval
    // The restart, as a checkpoint continues: times from the stop on, first step the one it carried.
    State r = seen.state;
    std::vector<double> rest{seen.t};
    for (double t : times)
      if (t > seen.t) rest.push_back(t);
    std::vector<State> restarted;
    integrate_observed(chain, r, rest, [&](const State& x, double) {
      restarted.push_back(x);
      return true;
    }, options(k), {}, seen.next_step);
    REQUIRE(restarted.size() == rest.size());
    for (std::size_t i = 1; i < rest.size(); ++i) {  // every later observation, bit for bit
      const State& same = full_observed[full_observed.size() - rest.size() + i];
      CHECK(std::memcmp(restarted[i].data(), same.data(), same.size() * sizeof(double)) == 0);
    }
  }
}

TEST_CASE("tolerances below what double precision resolves are refused, naming abs-tol") {
  IntegratorOptions o;
  o.abs_tol = 1e-300;
  o.rel_tol = 0;
  CHECK_THROWS_WITH_AS(validate(o), doctest::Contains("abs-tol + rel-tol must be at least 1e-15"), InvalidParameter);
  o.rel_tol = 1e-16;
  CHECK_THROWS_AS(validate(o), InvalidParameter);
  o.rel_tol = 1e-15;  // at the floor: accepted
  CHECK_NOTHROW(validate(o));
  o.rel_tol = 0;
  o.abs_tol = 1e-15;
  CHECK_NOTHROW(validate(o));
  o.abs_tol = 1e-300;
  o.stepper = StepperKind::srkn11b;  // the fixed-step steppers do not use them
  CHECK_NOTHROW(validate(o));

  using namespace lrchain::test;
  const fs::path out = fs::temp_directory_path() / ("lrchain-tolerance-" + std::to_string(::getpid()));
  fs::remove_all(out);
  const auto r = run_lrchain(words("simulate bright --branch optical --theta pi/2 --sites 101 --periods 2 --stepper rkf78 "
                                   "--abs-tol 1e-300 --rel-tol 0 --out " + out.string()));
  CHECK(r.exit_code == 2);
  CHECK(r.err.find("abs-tol") != std::string::npos);
  CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("CLI: SIGINT stops rkf78 inside a long interval between samples within seconds, exit 130 with a checkpoint") {
  // One sample interval of 400 T_b on 20001 sites: minutes of rkf78 steps before the next sample.
  const fs::path out = fs::temp_directory_path() / ("lrchain-step-stop-" + std::to_string(::getpid()));
  fs::remove_all(out);
  ProcessOptions o;
  o.capture_stdout = o.capture_stderr = true;
  ChildProcess child({LRCHAIN_CLI, "simulate", "bright", "--branch", "optical", "--theta", "pi/2", "--sites", "20001",
                      "--periods", "400", "--sample-every", "400", "--spacetime-every", "400", "--snapshots", "0",
                      "--stepper", "rkf78", "--no-figures", "--out", out.string()},
                     o);
  // Its handlers are up (SigCgt) once the run is under way.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  bool running = false;
  while (!running && std::chrono::steady_clock::now() < give_up) {
    std::ifstream status("/proc/" + std::to_string(child.pid()) + "/status");
    for (std::string line; std::getline(status, line);)
      if (line.rfind("SigCgt:", 0) == 0) running = (std::stoull(line.substr(7), nullptr, 16) >> (SIGINT - 1) & 1ULL) != 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  REQUIRE(running);
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // well inside the first interval
  const auto sent = std::chrono::steady_clock::now();
  child.send_signal(SIGINT);
  const ProcessResult r = child.wait();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  CHECK(seconds < 10);
  CHECK(r.exit_code == 130);
  CHECK(r.error_output.find("checkpoint at t = ") != std::string::npos);
  CHECK(fs::exists(out / "checkpoint.bin"));
  fs::remove_all(out);
}
