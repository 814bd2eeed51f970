#pragma once
// Floquet multipliers of a dark breather (theta = pi edge, odd ring) on a large lattice: its localized
// modes from a window ring carrying the breather, certified on the full lattice, and the continuous
// spectrum from the background plane wave's own Floquet-Bloch multipliers.
//   1. background: the far field of Z(0) (the two sites opposite the dip), polished by Newton on an
//      even ring of 10 sites to the exact 2-site-periodic plane wave at omega_b; the columns of its
//      monodromy for the 4 F unknowns of one 2-site cell (F fields; positions, velocities) on a ring of
//      ring_sites sites (doubled until their weight beyond a quarter of the ring is below
//      truncation_tolerance) give the Bloch monodromy B(Q) = sum_d G(d) exp(-i Q d) (d: cells) at
//      every cell wavenumber Q in [0, pi]; its eigenvalues are the plane wave's multipliers on the
//      infinite lattice (at Q = 0 without the trivial ones nearest +1: 2, 4 in strain form). The
//      largest on the ring's own wavenumber grid is certified by its residual on the background ring.
//   2. window: the sites out from the dip whose deviation from the background (the nearer of its two
//      values) exceeds `fraction` of the background's amplitude (or 10 x the median deviation, where
//      the far field's own error is larger), plus `margin` each side (odd, at most `cap`), as a ring of
//      the same model; the breather solved there by Newton from Z(0) restricted
//      to it (the same omega_b; an odd ring as the full one); its dense monodromy, and a second window
//      1.5x wider. Localized eigenvectors (windowed_floquet.hpp's rule) certified by their residual on
//      the full lattice (window_modes.hpp).
//   3. verdict: unstable as soon as an instability is certified (localized, or the background's);
//      stable when every listed localized multiplier is certified, the trivial ones are found, the
//      background's multipliers lie on the unit circle and the window's extended modes too; otherwise
//      none, with the reason (e.g. an extended window mode off the circle on a stable background: a
//      finite-size instability of a ring, which the window cannot certify for the full one).
#include <complex>
#include <optional>
#include <string>

#include <Eigen/Dense>

#include "lrchain/index.hpp"
#include "lrchain/sim/bright/windowed_floquet.hpp"
#include "lrchain/sim/dark/floquet.hpp"
#include "lrchain/sim/dark/shooting.hpp"
#include "lrchain/sim/dark/shooting_problem.hpp"

namespace lrchain::sim::dark {

// The window's first ring at most 201 sites (cap; the check ring 303): a wider one of a two-field
// lattice costs minutes (401 / 603 sites of the resonant chain: 630 s).
inline bright::WindowedFloquetOptions dark_window_options() {
  bright::WindowedFloquetOptions o;
  o.cap = 201;
  return o;
}

struct WindowedDarkFloquetOptions {
  bright::WindowedFloquetOptions window = dark_window_options();  // count, fraction, margin, cap, tolerances
  NewtonOptions newton;                   // the window's and the background's Newton
  Index background_sites = 64;            // first ring of the background's monodromy columns (even)
  Index background_cap = 1024;            // ... doubled at most to this
  double truncation_tolerance = 1e-13;    // column weight beyond a quarter of the ring / column norm
  Index wavenumbers = 1025;               // cell wavenumbers Q sampled on [0, pi]
};

// The background plane wave's Floquet-Bloch multipliers (empty reason: computed).
struct BackgroundSpectrum {
  Eigen::MatrixXd cell;                  // the plane wave's Z(0) on two sites (fields x 2)
  Index ring_sites = 0;                  // ring of the monodromy columns
  Index wavenumbers = 0;
  double newton_residual = 0;            // max|F| of the background's Newton
  double amplitude = 0;                  // max |Z| of the background
  double truncation = 0;                 // the columns' weight beyond a quarter of the ring, relative
  double max_modulus = 0;                // over all sampled wavenumbers
  double max_wavenumber = 0;             // site wavenumber q = Q/2 in [0, pi/2] of the largest
  std::complex<double> ring_leading;     // the largest on the ring's wavenumber grid
  double ring_residual = 0;              // its ||M v - lambda v|| / ||v|| on the background ring
  std::optional<FloquetResult> unstable; // classify_multipliers of the multipliers off the circle (none: on it)
  std::string reason;                    // why it was not computed
};

struct WindowedDarkFloquet {
  bright::WindowedFloquet window;        // the window's modes, certified ones (its verdict: the localized ones only)
  BackgroundSpectrum background;
  Index window_newton_iterations = 0;    // Newton on the first window
  double window_newton_residual = 0;
  std::optional<FloquetResult> verdict;  // the breather's (nullopt: reason)
  std::string verdict_reason;
  double background_seconds = 0;
};

// The windowed multipliers of the dark breather Z(0) = [z0, 0] of `shooting` (an odd ring at a theta =
// pi edge) at omega_b; `lattice` as for the bright window.
WindowedDarkFloquet windowed_dark_floquet(const DarkShooting& shooting, const bright::WindowLattice& lattice,
                                          const Eigen::VectorXd& z0, double omega_b,
                                          const WindowedDarkFloquetOptions& options = {});

}  // namespace lrchain::sim::dark
