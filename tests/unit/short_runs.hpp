#pragma once
// Pieces the run tests share: a short drive run and the parameter a refusal names.
#include <string>

#include "lrchain/errors.hpp"
#include "lrchain/sim/drive_run.hpp"

namespace lrchain::test {

// A short drive run (100 beads to t = 60) with an explicit memory budget, so the reach does not
// depend on the machine.
inline sim::DriveRunConfig short_drive() {
  sim::DriveRunConfig d;
  d.beads = 100;
  d.t_end = 60;
  d.t_m = 40;
  d.sample_every = 1;
  d.spacetime_every = 2;
  d.snapshot_times = {60};
  d.front_fit_start = 0;
  d.front_fit_end = 60;
  d.max_memory = 64.0 * (1 << 20);  // 64 MiB
  return d;
}

// The parameter named by the InvalidParameter that f throws ("" if none is thrown).
template <class F>
std::string refused_parameter(F&& f) {
  try {
    f();
  } catch (const InvalidParameter& e) {
    return e.parameter();
  }
  return "";
}

}  // namespace lrchain::test
