#pragma once
// Exact periodic standing waves of a reflection-symmetric model lattice (docs/waves.md, "Standing waves"):
// the time-periodic orbit u_f[n](t) = sum_k c_{f,n,k} cos(k omega t) (even in t: the time phase is fixed)
// on a ring of sites holding theta = 2 pi j / sites, seeded by the sum of the two counter-propagating
// linear waves A Re(K_f e^{i theta n}) cos(omega t), solved by Gauss-Newton on the H+1 collocation times
// omega t_i = pi i / H of the half period (omega^2 u'' = ... is even in t), with the amplitude (the cos(theta n)
// cos(omega t) part of the first field is A), the spatial phase (its sin(theta n) cos(omega t) part is 0)
// and, in a translation-invariant model, the mean of the first field (0) fixed. Its Floquet multipliers
// are those of the period map of the variational equations on the ring.
#include <complex>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"

namespace lrchain::sim::wave {

// A reflection u_f[n] -> sign u_f[offset_f - n] of the ring that maps solutions to solutions.
struct ReflectionSymmetry {
  int sign = 1;
  std::vector<int> offsets;  // per field, offsets[0] = 0
};

// The reflection the ring's accelerations commute with (sign +-1, offsets in {-1, 0, 1}), tried at a
// random small state; nullopt when there is none (no standing wave: the model is not symmetric).
std::optional<ReflectionSymmetry> reflection_symmetry(const CompiledLattice& ring);

struct StandingWaveOptions {
  Index initial_harmonics = 8;      // H: cosines cos(k omega t), k = 0..H
  Index max_harmonics = 128;        // H doubles up to this while the tail is above tail_tolerance
  double tail_tolerance = 1e-10;    // largest |c_{f,n,k}| (k > 2H/3) relative to A
  double newton_tolerance = 1e-11;  // max |residual| relative to omega_linear^2 A
  Index max_newton_steps = 30;
};

struct StandingWave {
  double theta = 0, amplitude = 0;     // A: the cos(theta n) cos(omega t) part of the first field
  double omega = 0, omega_linear = 0;  // the wave's frequency and the branch's linear one at theta
  Index sites = 0;                     // the ring the wave was solved on (theta = 2 pi j / sites)
  Index harmonics = 0;                 // H used
  double tail = 0, residual = 0;
  Index newton_steps = 0;
  Eigen::MatrixXd coefficients;        // c_{f,n,k}: row f * sites + n, column k (k = 0..H)
  std::optional<double> least_contact_overlap;  // one-sided contacts: least overlap along the orbit
};

// The standing wave of `amplitude` on `ring` (periodic, displacement form, theta = 2 pi j / sites) on the
// branch of `mode`, seeded by `seed` or the linear standing wave. Throws NumericalFailure (Newton does
// not converge, the harmonics do not decay, a contact opens).
StandingWave solve_standing_wave(CompiledLattice& ring, const BlochMode& mode, double theta, double amplitude,
                                 const StandingWaveOptions& options = {}, const StandingWave* seed = nullptr);

struct StandingWaveBranch {
  std::vector<StandingWave> waves;
  std::optional<std::string> stopped;
  std::optional<double> stopped_at;
};
// The branch through increasing `amplitudes`, each wave seeding the next; stops at the first refusal.
StandingWaveBranch continue_standing_wave(CompiledLattice& ring, const BlochMode& mode, double theta,
                                          const std::vector<double>& amplitudes, const StandingWaveOptions& options = {});

// The wave's positions u_f[n](t) at time t on a ring of `sites` (a multiple of wave.sites; fields x sites,
// field-major).
void standing_positions(const StandingWave& wave, Index sites, double t, Eigen::VectorXd& q);

// Floquet multipliers of the standing wave's period map on `ring` (sites a multiple of the wave's):
// the monodromy of X'' = J(u(t)) X over 2 pi / omega (Odeint dopri5, tolerance 1e-11), its eigenvalues.
struct StandingFloquet {
  std::vector<std::complex<double>> multipliers;  // by decreasing modulus
  double largest_modulus = 0;
  bool stable = true;                             // largest_modulus <= 1 + tolerance
};
StandingFloquet standing_floquet(CompiledLattice& ring, const StandingWave& wave, double tolerance = 1e-6);

}  // namespace lrchain::sim::wave
