#pragma once
// Krein signatures of the Floquet multipliers on the unit circle (MacKay, in Hamiltonian Dynamical
// Systems, Adam Hilger 1987; Aubry, Physica D 103, 201 (1997), Sec. 4): for a multiplier
// lambda = exp(i theta), 0 < theta < pi, with eigenvector v of the monodromy matrix, the sign of
// Im(v^H J v), J the symplectic form of the displacements and velocities (u, udot):
// J = [[0, diag(m)], [-diag(m), 0]], m the mass of each position. A complex quadruplet can only leave
// the circle where two multipliers of opposite signature meet (a Krein collision): the onset of an
// oscillatory instability.
//
// Strain form (a translation-invariant model on a ring: r[n] = u_0[n] - u_0[n-1], w_f[n] = u_f[n] - u_0[n]
// and their velocities) has no form of this shape; its eigenvector is lifted to displacements first:
// u_0[n] = sum_{j <= n} r[j], u_f = u_0 + w_f, the velocities likewise, each less its centre of mass.
// The lift is a displacement perturbation of the ring because a multiplier lambda != 1 has sum r = 0
// and sum rdot = 0 (the total strain S = sum r and its rate obey S' = S + T Sdot, Sdot' = Sdot over a
// period, so lambda S = S + T Sdot and lambda Sdot = Sdot force both to 0). The constant left in u_0
// does not matter: it adds c times the total momentum to the form, and the momentum of the lift is 0
// (the momentum P and the centre of mass X obey P' = P, X' = X + T P / M, so lambda != 1 forces P = 0
// and X = 0 on the displacement eigenvector; the lift differs from it by a uniform displacement and
// velocity, which the centre-of-mass subtractions remove: the lift is that eigenvector).
#include <complex>
#include <vector>

#include <Eigen/Dense>

#include "lrchain/index.hpp"

namespace lrchain::sim::bright {

struct KreinMultiplier {
  std::complex<double> lambda;  // on the upper unit circle (Im lambda > 0)
  // +1 or -1; 0 (strain form only): undetermined, the eigenvector does not close on the ring (|sum r|
  // above 1e-6 of the L1 size of its positions, or |sum rdot| of its velocities)
  int signature = 0;
};

// The signatures of the multipliers with ||lambda| - 1| <= unit_tolerance, Im lambda > 1e-9 and
// |lambda - 1| > trivial_radius (the trivial ones, BrightFloquet::trivial_distance), ordered by angle;
// `masses` has one entry per position (half the size of `monodromy`), field-major. Displacement form.
std::vector<KreinMultiplier> krein_signatures(const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& masses,
                                              double unit_tolerance, double trivial_radius = 0);

// The same for the strain form of a periodic ring of `sites` sites per field (the lift above);
// `masses` as above (field f's mass on each of its sites). Throws InvalidParameter("sites") unless
// sites divides masses.size().
std::vector<KreinMultiplier> strain_krein_signatures(const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& masses,
                                                     Index sites, double unit_tolerance, double trivial_radius = 0);

// The displacement-form perturbation [u, udot] of a strain-form ring perturbation v = [r, w_1.., rdot,
// w_1dot..] (field-major, `sites` per field), lifted as above (centre of mass and total momentum 0).
Eigen::VectorXcd ring_displacements_of_strain(const Eigen::VectorXcd& v, const Eigen::VectorXd& masses, Index sites);

}  // namespace lrchain::sim::bright
