#pragma once
// Exact periodic travelling waves u_f[n](t) = U_f(theta n - omega t) of a model lattice (docs/waves.md):
// omega^2 U''(xi) = a(U(xi + m theta), m in the stencil) on the 2H+1 collocation phases (harmonic
// balance), solved by Gauss-Newton for (U, omega) with the phase fixed (the first harmonic of the
// first field is A cos xi: its sine part 0, its cosine part the amplitude A) and, in a
// translation-invariant model, the mean of the first field 0. H doubles until the upper third of the
// harmonics falls below a tolerance. Seeded by the linear Bloch mode (omega, K) at theta, continued
// in A.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/model_lattice_bloch.hpp"
#include "lrchain/sim/wave/wave_collocation.hpp"

namespace lrchain::sim::wave {

struct TravellingWaveOptions {
  Index initial_harmonics = 8;     // H of the first solve (2H+1 phases)
  Index max_harmonics = 128;       // H is doubled up to this while the tail is above tail_tolerance
  double tail_tolerance = 1e-10;   // largest harmonic k > 2H/3 of any field, relative to A
  double newton_tolerance = 1e-11; // max |residual| relative to omega_linear^2 A
  Index max_newton_steps = 30;
};

// One solved wave.
struct TravellingWave {
  double theta = 0, amplitude = 0;    // amplitude A: U_0 = A cos xi + (other harmonics)
  double omega = 0, omega_linear = 0; // the wave's frequency, the linear branch frequency at theta
  Index harmonics = 0;                // H used (2H+1 collocation phases)
  double tail = 0;                    // largest |2 c_k| (k > 2H/3, any field) / A
  double residual = 0;                // max |omega^2 U'' - a| / (omega_linear^2 A)
  Index newton_steps = 0;
  bool translation_invariant = false; // the mean of U_0 was fixed to 0
  Eigen::VectorXd profile;            // U_f(xi_j), field-major: fields x (2H+1)
  std::optional<double> least_contact_overlap;  // one-sided contacts: least overlap along the wave
  Index resonance_harmonic = 0;       // the harmonic k (2..) nearest a linear resonance k omega = omega_b(k theta)
  double resonance_distance = 0;      // its min_b |k omega - omega_b(k theta)| / omega (0 when not computed)
};

// The wave of amplitude `amplitude` on the branch of `mode` (the linear Bloch mode at lattice.theta()),
// seeded by `seed` (a solved wave of the same lattice) or the linear mode. Throws NumericalFailure
// with the reason where no wave is found: Newton fails (near a harmonic resonance, named), the
// harmonics do not decay within max_harmonics, or a one-sided contact opens.
TravellingWave solve_travelling_wave(WaveLattice& lattice, const BlochMode& mode, double amplitude,
                                     const TravellingWaveOptions& options = {},
                                     const TravellingWave* seed = nullptr);

// The branch omega(A) through `amplitudes` (increasing), each seeded by the previous wave; stops at
// the first amplitude without a wave and says why in `stopped`.
struct WaveBranch {
  std::vector<TravellingWave> waves;
  std::optional<std::string> stopped;  // the refusal of the first amplitude without a wave
  std::optional<double> stopped_at;    // that amplitude
};
WaveBranch continue_travelling_wave(WaveLattice& lattice, const BlochMode& mode, const std::vector<double>& amplitudes,
                                    const TravellingWaveOptions& options = {});

// Harmonic k (0..H) of field f of a solved wave: complex c_k of U_f = sum_k c_k e^{i k xi}.
std::vector<std::complex<double>> wave_harmonics(const TravellingWave& wave, Index field);

// U(xi) = sum_k c_k e^{i k xi} (c_{-k} = conj c_k) and its derivative dU/dxi, from the harmonics c_0..c_H
// of wave_harmonics.
void profile_at(const std::vector<std::complex<double>>& harmonics, double xi, double& u, double& du);

}  // namespace lrchain::sim::wave
