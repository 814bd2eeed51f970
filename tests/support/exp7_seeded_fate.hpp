#pragma once
// The fate of experiment 7's wave seeded as the paper seeds it (Sec. 5.1, eq:cimi): the acoustic wave at
// theta0 = 252 pi / 401, A = 0.03, times 1 + 0.01 cos(2 pi n / 401) on the ring of 401 sites, no noise,
// 8500 carrier periods (t ~ 45400), on any model with an acoustic branch.
#include <numbers>

#include "lrchain/jobs/wave_job.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

namespace lrchain::test {

inline jobs::wave::WaveResult exp7_seeded_fate(const Model& model) {
  jobs::wave::WaveConfig c;
  c.step = jobs::wave::WaveStep::fate;
  c.model = &model;
  c.kernels = &sim::lattice_kernels_of(model);
  c.branch = "acoustic";
  c.theta = 252 * std::numbers::pi / 401;
  c.amplitude = 0.03;
  c.k_points = 60;
  c.ring_sites = 401;
  c.noise = 0;
  c.modulation = 0.01;
  c.periods = 8500;
  return jobs::wave::run(c);
}

}  // namespace lrchain::test
