#pragma once
// Krein signatures of the Floquet multipliers on the unit circle (MacKay, in Hamiltonian Dynamical
// Systems, Adam Hilger 1987; Aubry, Physica D 103, 201 (1997), Sec. 4): for a multiplier
// lambda = exp(i theta), 0 < theta < pi, with eigenvector v of the monodromy matrix, the sign of
// Im(v^H J v), J the symplectic form of the state (q, qdot): J = [[0, diag(m)], [-diag(m), 0]], m the
// mass of each position. A complex quadruplet can only leave the circle where two multipliers of
// opposite signature meet (a Krein collision): the onset of an oscillatory instability. The form is
// canonical only in displacement form; the strain form (a mean flow) has none of this shape.
#include <complex>
#include <vector>

#include <Eigen/Dense>

namespace lrchain::sim::bright {

struct KreinMultiplier {
  std::complex<double> lambda;  // on the upper unit circle (Im lambda > 0)
  int signature = 0;            // +1 or -1
};

// The signatures of the multipliers with ||lambda| - 1| <= unit_tolerance, Im lambda > 1e-9 and
// |lambda - 1| > trivial_radius (the trivial ones, BrightFloquet::trivial_distance), ordered by angle;
// `masses` has one entry per position (half the size of `monodromy`).
std::vector<KreinMultiplier> krein_signatures(const Eigen::MatrixXd& monodromy, const Eigen::VectorXd& masses,
                                              double unit_tolerance, double trivial_radius = 0);

}  // namespace lrchain::sim::bright
