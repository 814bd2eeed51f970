// Floquet-Bloch spectra of travelling waves (wave_stability.hpp).
#include "lrchain/sim/wave/wave_stability.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

#include <boost/math/tools/minima.hpp>

namespace lrchain::sim::wave {

BlochSpectrum::BlochSpectrum(WaveLattice& lattice, const TravellingWave& wave)
    : lattice_(&lattice),
      fields_(lattice.fields()),
      points_(2 * wave.harmonics + 1),
      omega_(wave.omega),
      grid_(wave.harmonics) {
  lattice.prepare(grid_, wave.profile);
  lattice.jacobian_blocks(blocks_);
  operator_.setZero(2 * fields_ * points_, 2 * fields_ * points_);
}

// lambda (W, V) = (V, (-omega^2 D2 + sum_m e^{i K m} J_m S_m) W + 2 omega D V), V = lambda W.
Eigen::VectorXcd BlochSpectrum::eigenvalues(double K) {
  const Index F = fields_, N = points_, n = F * N;
  operator_.setZero();
  operator_.block(0, n, n, n).setIdentity();
  for (Index g = 0; g < F; ++g) {
    operator_.block(n + g * N, g * N, N, N) = (-omega_ * omega_ * grid_.second_derivative).cast<std::complex<double>>();
    operator_.block(n + g * N, n + g * N, N, N) = (2 * omega_ * grid_.first_derivative).cast<std::complex<double>>();
  }
  for (std::size_t s = 0; s < blocks_.size(); ++s) {
    const int m = lattice_->shifts()[s];
    const std::complex<double> phase = std::polar(1.0, K * double(m));
    const Eigen::MatrixXd& S = lattice_->shift_matrix(m);
    for (Index g = 0; g < F; ++g)
      for (Index f = 0; f < F; ++f)
        operator_.block(n + g * N, f * N, N, N) +=
            phase * (blocks_[s].row(g + F * f).transpose().asDiagonal() * S).cast<std::complex<double>>();
  }
  solver_.compute(operator_, false);
  return solver_.eigenvalues();
}

double BlochSpectrum::growth_rate(double K) { return eigenvalues(K).real().maxCoeff(); }

RingGrowth ring_growth(WaveLattice& lattice, const TravellingWave& wave, Index sites, double unstable_tolerance) {
  BlochSpectrum spectrum(lattice, wave);
  RingGrowth r;
  for (Index m = 1; 2 * m <= sites; ++m) {
    const double K = 2 * std::numbers::pi * double(m) / double(sites);
    const double rate = spectrum.growth_rate(K);
    if (rate > unstable_tolerance * wave.omega && rate > r.rate) r = {rate, K};
  }
  return r;
}

WaveStability wave_stability(WaveLattice& lattice, const TravellingWave& wave, const WaveStabilityOptions& o) {
  BlochSpectrum spectrum(lattice, wave);
  WaveStability r;
  const double floor = o.unstable_tolerance * wave.omega;
  for (Index i = 1; i <= o.k_points; ++i) {
    const double x = double(i) / double(o.k_points);
    r.k.push_back(std::numbers::pi * x * x);
    const double rate = spectrum.growth_rate(r.k.back());
    r.growth_rate.push_back(rate > floor ? rate : 0.0);
  }
  for (std::size_t i = 0; i < r.k.size(); ++i) {
    if (r.growth_rate[i] <= 0) continue;
    if (r.bands.empty() || i == 0 || r.growth_rate[i - 1] <= 0) r.bands.push_back({r.k[i], r.k[i], 0, 0});
    UnstableBand& b = r.bands.back();
    b.k_to = r.k[i];
    if (r.growth_rate[i] > b.largest_rate) {
      b.largest_rate = r.growth_rate[i];
      b.at_k = r.k[i];
    }
  }
  r.stable = r.bands.empty();
  // Each band's largest rate refined by Brent between the grid neighbours of its largest sample.
  for (UnstableBand& b : r.bands) {
    const auto it = std::find(r.k.begin(), r.k.end(), b.at_k);
    const std::size_t i = std::size_t(it - r.k.begin());
    const double lo = i == 0 ? 0.5 * r.k[0] : r.k[i - 1], hi = i + 1 == r.k.size() ? std::numbers::pi : r.k[i + 1];
    const auto best = boost::math::tools::brent_find_minima([&](double K) { return -spectrum.growth_rate(K); }, lo, hi, 40);
    if (-best.second > b.largest_rate) {
      b.largest_rate = -best.second;
      b.at_k = best.first;
    }
    if (b.largest_rate > r.largest_rate) {
      r.largest_rate = b.largest_rate;
      r.at_k = b.at_k;
    }
  }
  return r;
}

}  // namespace lrchain::sim::wave
