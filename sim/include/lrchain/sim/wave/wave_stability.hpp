#pragma once
// Floquet-Bloch stability of a travelling wave (docs/waves.md): a perturbation
// w_n(t) = e^{lambda t + i K n} W(theta n - omega t), W 2 pi-periodic, solves the quadratic eigenvalue
// problem  lambda^2 W - 2 lambda omega W' + omega^2 W'' - sum_m e^{i K m} J_m(xi) W(xi + m theta) = 0
// (J_m the Jacobian blocks of the accelerations along the wave), linearised to first order in
// (W, lambda W) on the wave's collocation phases and solved densely (Eigen ComplexEigenSolver).
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/sim/wave/travelling_wave.hpp"

namespace lrchain::sim::wave {

struct WaveStabilityOptions {
  Index k_points = 200;             // K_i = pi (i / k_points)^2, i = 1..k_points: dense near K = 0 (the MI band)
  double unstable_tolerance = 1e-9; // Re lambda > tolerance * omega counts as growth
};

struct UnstableBand {
  double k_from = 0, k_to = 0;      // grid wavenumbers where the growth starts and ends
  double largest_rate = 0, at_k = 0;
};

struct WaveStability {
  std::vector<double> k, growth_rate;  // max Re lambda at each K (0 where below the tolerance)
  std::vector<UnstableBand> bands;
  double largest_rate = 0, at_k = 0;   // over all K, refined between grid points (Brent)
  bool stable = true;
};

// max Re lambda of the Floquet-Bloch spectrum at one K, for the wave prepared on `lattice`.
class BlochSpectrum {
 public:
  BlochSpectrum(WaveLattice& lattice, const TravellingWave& wave);
  // Every eigenvalue lambda at K.
  Eigen::VectorXcd eigenvalues(double K);
  double growth_rate(double K);  // max Re lambda
 private:
  WaveLattice* lattice_;
  Index fields_, points_;
  double omega_;
  CollocationGrid grid_;
  std::vector<Eigen::MatrixXd> blocks_;
  Eigen::MatrixXcd operator_;
  Eigen::ComplexEigenSolver<Eigen::MatrixXcd> solver_;
};

// Growth rate over K in (0, pi], the unstable bands and the largest rate with its K.
WaveStability wave_stability(WaveLattice& lattice, const TravellingWave& wave, const WaveStabilityOptions& options = {});

// The largest growth rate among the perturbations a ring of `sites` sites holds, K = 2 pi m / sites
// (m = 1..sites/2), and its K; rate 0 (K 0) when none exceeds unstable_tolerance x omega.
struct RingGrowth {
  double rate = 0, at_k = 0;
};
RingGrowth ring_growth(WaveLattice& lattice, const TravellingWave& wave, Index sites, double unstable_tolerance);

}  // namespace lrchain::sim::wave
