#pragma once
// Direct integration of an exact bright breather on its lattice (issue 29, `bright evolve`): the
// state [Z(0) + dq, dv] advanced period by period with the shooting's own integrator (shooting.hpp),
// and per period m = 0..M the deviation max|[Z, Zdot](m T_b) - [Z(0), 0]| and the energy. A stable
// breather keeps its profile (the deviation stays at the level of the perturbation and the Newton
// tolerance); an unstable one departs like |lambda_max|^m (Floquet), so ln(deviation) grows at the
// rate ln|lambda_max| / T_b, fitted by least squares while the deviation stays small.
#include <optional>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/dark/shooting.hpp"

namespace lrchain::sim::bright {

struct BrightEvolutionSample {
  double t = 0;          // m T_b
  double deviation = 0;  // max-norm of [Z(m T_b) - Z(0), Zdot(m T_b)] (positions and velocities)
  double energy = 0;     // the lattice energy at m T_b (0 when the model has no potential)
};

struct BrightEvolution {
  double period = 0;                          // T_b = 2 pi / omega_b
  std::vector<BrightEvolutionSample> samples;  // m = 0..periods (samples[0]: the perturbed start)
  bool has_energy = false;                    // the model's forces have a potential
  double profile_drift = 0;   // max over m >= 1 of deviation(m) / max|Z(0)|
  double energy_drift = 0;    // max over m of |E(m T_b) - E(0)| / |E(0)| (has_energy)
  // The least-squares slope of ln deviation(m) against t over m = 0..fit_last, the periods before the
  // deviation first reaches saturation x max|Z(0)| (nullopt: fewer than 3 such periods, or a zero deviation)
  std::optional<double> growth_rate;
  Index fit_last = 0;
};

// Evolves Z(0) (positions, field-major, velocities 0) plus `perturbation` (2 positions entries, or
// empty) over `periods` periods T_b on the shooting's lattice; `saturation` bounds the growth fit.
BrightEvolution evolve_bright_breather(const dark::DarkShooting& shooting, const Eigen::VectorXd& z0, double omega_b,
                                       Index periods, const Eigen::VectorXd& perturbation, double saturation = 0.1);

}  // namespace lrchain::sim::bright
