#pragma once
// The anti-continuum start of an exact bright breather (MacKay & Aubry, Nonlinearity 7, 1623 (1994)):
// at coupling 0 every cell of an on-site lattice is its own oscillator, so one of them (site-centred) or
// two neighbours (bond-centred: in phase at a theta = 0 edge, out of phase at theta = pi) oscillating at
// omega_b with the rest at rest is an exact breather; continued in the coupling it becomes the breather
// of the coupled lattice (jobs/bright_breather_job.hpp, start = anti-continuum).
#include <Eigen/Dense>

#include "lrchain/sim/dark/shooting.hpp"

namespace lrchain::sim::bright {

struct AntiContinuumOrbit {
  Eigen::VectorXd z0;       // Z(0) at rest, field-major: the excited oscillators' amplitude, zero elsewhere
  double amplitude = 0;     // x0 of the centre oscillator (field 0; a bond partner has its own, in z0)
};

// `uncoupled`: the time-reversible shooting of the lattice at coupling 0 (displacement form, `sites`
// odd, site i at n = i - (sites - 1)/2). The amplitude x0 with x(0) = x0, xdot(0) = 0, xdot(T_b/2) = 0 at
// T_b = 2 pi / omega_b: the smallest root of the half-period velocity over a logarithmic scan of x0 in
// [1e-4, 100] (80 points), refined by bisection to 1e-14 relative. InvalidParameter("omega_b") when no
// amplitude oscillates at omega_b.
AntiContinuumOrbit anti_continuum_orbit(const dark::DarkShooting& uncoupled, double omega_b, Index sites, bool bond,
                                        bool staggered);

}  // namespace lrchain::sim::bright
