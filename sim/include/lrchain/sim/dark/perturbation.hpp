#pragma once
// Perturbations of a dark breather's start [Z(0), Zdot(0)] for `dark evolve --perturb` (issue 27:
// watch an instability grow): along the eigenvector of the monodromy's largest-modulus multiplier,
// or random. Both scaled to the max-norm `size`.
#include <Eigen/Dense>
#include <complex>
#include <cstdint>

#include "lrchain/index.hpp"

namespace lrchain::sim::dark {

struct DarkPerturbation {
  Eigen::VectorXd vector;                // 2 positions entries: positions then velocities
  std::complex<double> multiplier = 0;   // (unstable) the eigenvector's Floquet multiplier
};

// The real eigenvector (or the real part of a complex one, else its imaginary part) of the
// monodromy's largest-modulus multiplier, scaled to max|entry| = size, its largest entry positive.
DarkPerturbation unstable_perturbation(const Eigen::MatrixXd& monodromy, double size);

// Positions uniform in [-size, size] from a Mersenne Twister (mt19937_64) seeded with `seed`,
// velocities zero: the same seed gives the same perturbation on every machine.
DarkPerturbation random_perturbation(Index positions, double size, std::uint64_t seed);

}  // namespace lrchain::sim::dark
