// Collocation grid and the model's forces along a travelling wave (wave_collocation.hpp).
#include "lrchain/sim/wave/wave_collocation.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "lrchain/errors.hpp"

namespace lrchain::sim::wave {

namespace {

constexpr Index kStencilRadius = 7;  // the chain's half length: lattice shifts up to 7 (models use <= 3)

// (1/N) sum_{|k|<=H} e^{i k x} and its first and second derivatives in x (real: the sums of cosines/sines).
double kernel_value(Index H, double x) {
  double s = 1;
  for (Index k = 1; k <= H; ++k) s += 2 * std::cos(double(k) * x);
  return s / double(2 * H + 1);
}

}  // namespace

CollocationGrid::CollocationGrid(Index H) : harmonics(H), points(2 * H + 1) {
  // Circulant: entry (j, l) depends on (j - l) mod N only.
  const Index N = points;
  std::vector<double> d1(static_cast<std::size_t>(N), 0.0), d2(static_cast<std::size_t>(N), 0.0);
  for (Index d = 0; d < N; ++d) {
    const double x = phase(d);
    for (Index k = 1; k <= H; ++k) {
      d1[std::size_t(d)] -= 2 * double(k) * std::sin(double(k) * x) / double(N);
      d2[std::size_t(d)] -= 2 * double(k * k) * std::cos(double(k) * x) / double(N);
    }
  }
  first_derivative.resize(N, N);
  second_derivative.resize(N, N);
  for (Index j = 0; j < N; ++j)
    for (Index l = 0; l < N; ++l) {
      first_derivative(j, l) = d1[std::size_t((j - l + N) % N)];
      second_derivative(j, l) = d2[std::size_t((j - l + N) % N)];
    }
}

double CollocationGrid::phase(Index j) const { return 2 * std::numbers::pi * double(j) / double(points); }

Eigen::MatrixXd CollocationGrid::shift(double s) const {
  std::vector<double> g(static_cast<std::size_t>(points));
  for (Index d = 0; d < points; ++d) g[std::size_t(d)] = kernel_value(harmonics, phase(d) + s);
  Eigen::MatrixXd S(points, points);
  for (Index j = 0; j < points; ++j)
    for (Index l = 0; l < points; ++l) S(j, l) = g[std::size_t((j - l + points) % points)];
  return S;
}

std::vector<std::complex<double>> harmonics_of(const double* samples, Index points) {
  const Index H = (points - 1) / 2;
  std::vector<std::complex<double>> c(static_cast<std::size_t>(H + 1));
  for (Index k = 0; k <= H; ++k) {
    std::complex<double> sum = 0;
    for (Index j = 0; j < points; ++j)
      sum += samples[j] * std::polar(1.0, -2 * std::numbers::pi * double(k * j) / double(points));
    c[std::size_t(k)] = sum / double(points);
  }
  return c;
}

std::vector<double> resampled(const double* samples, Index points, Index harmonics_new) {
  const std::vector<std::complex<double>> c = harmonics_of(samples, points);
  const Index N = 2 * harmonics_new + 1, H = std::min<Index>(harmonics_new, Index(c.size()) - 1);
  std::vector<double> out(static_cast<std::size_t>(N));
  for (Index j = 0; j < N; ++j) {
    const double xi = 2 * std::numbers::pi * double(j) / double(N);
    double u = c[0].real();
    for (Index k = 1; k <= H; ++k) u += 2 * (c[std::size_t(k)] * std::polar(1.0, double(k) * xi)).real();
    out[std::size_t(j)] = u;
  }
  return out;
}

WaveLattice::WaveLattice(const lrchain_lattice_kernels& kernels, std::vector<double> parameters, double theta)
    : parameters_(parameters),
      theta_(theta),
      fields_(kernels.fields),
      radius_(kStencilRadius),
      sites_(2 * kStencilRadius + 1),
      chain_(kernels, std::move(parameters), 2 * kStencilRadius + 1, false, LatticeForm::displacement) {
  const std::size_t size = std::size_t(fields_ * sites_);
  q_.assign(size, 0.0);
  a_.assign(size, 0.0);
  dq_.assign(size, 0.0);
  da_.assign(size, 0.0);
  // The stencil: the shifts whose Jacobian block is nonzero at rest or at small random states; the
  // symmetry: a uniform displacement of every field changes no acceleration at those states.
  std::mt19937 gen(20261128);
  std::uniform_real_distribution<double> small(-1e-3, 1e-3);
  std::vector<bool> used(std::size_t(sites_), false);
  translation_invariant_ = true;
  for (int trial = 0; trial < 3; ++trial) {
    for (double& x : q_) x = trial == 0 ? 0.0 : small(gen);
    double scale = 0;  // the largest Jacobian entry seen by the centre site
    for (Index f = 0; f < fields_; ++f)
      for (Index site = 0; site < sites_; ++site) {
        std::fill(dq_.begin(), dq_.end(), 0.0);
        dq_[std::size_t(f * sites_ + site)] = 1;
        chain_.jacobian_action(q_.data(), dq_.data(), da_.data());
        for (Index g = 0; g < fields_; ++g) {
          const double entry = da_[std::size_t(g * sites_ + radius_)];
          if (entry != 0) used[std::size_t(site)] = true;
          scale = std::max(scale, std::abs(entry));
        }
      }
    // A uniform displacement of every field, seen by the centre site (its stencil stays inside the chain).
    std::fill(dq_.begin(), dq_.end(), 1.0);
    chain_.jacobian_action(q_.data(), dq_.data(), da_.data());
    for (Index g = 0; g < fields_; ++g)
      if (std::abs(da_[std::size_t(g * sites_ + radius_)]) > 1e-12 * std::max(scale, 1.0)) translation_invariant_ = false;
  }
  for (Index site = 0; site < sites_; ++site)
    if (used[std::size_t(site)]) shifts_.push_back(int(site - radius_));
  if (used.front() || used.back())
    throw NumericalFailure("travelling wave: the model's forces reach further than " + std::to_string(radius_) +
                           " sites, more than the wave solver's chain holds");
}

void WaveLattice::prepare(const CollocationGrid& grid, const Eigen::VectorXd& profile) {
  if (points_ != grid.points || shift_matrices_.empty()) {
    points_ = grid.points;
    shift_matrices_.clear();
    for (Index m = -radius_; m <= radius_; ++m) shift_matrices_.push_back(grid.shift(double(m) * theta_));
  }
  shifted_.resize(std::size_t(sites_));
  for (Index m = -radius_; m <= radius_; ++m) {
    Eigen::VectorXd& out = shifted_[std::size_t(m + radius_)];
    out.resize(fields_ * points_);
    for (Index f = 0; f < fields_; ++f)
      out.segment(f * points_, points_) = shift_matrix(int(m)) * profile.segment(f * points_, points_);
  }
}

void WaveLattice::load_chain(Index j) {
  for (Index f = 0; f < fields_; ++f)
    for (Index site = 0; site < sites_; ++site)
      q_[std::size_t(f * sites_ + site)] = shifted_[std::size_t(site)](f * points_ + j);
}

void WaveLattice::accelerations(Eigen::VectorXd& a) {
  a.resize(fields_ * points_);
  for (Index j = 0; j < points_; ++j) {
    load_chain(j);
    chain_.acceleration(q_.data(), a_.data());
    for (Index g = 0; g < fields_; ++g) a(g * points_ + j) = a_[std::size_t(g * sites_ + radius_)];
  }
}

void WaveLattice::jacobian_blocks(std::vector<Eigen::MatrixXd>& blocks) {
  blocks.resize(shifts_.size());
  for (auto& b : blocks) b.setZero(fields_ * fields_, points_);
  for (Index j = 0; j < points_; ++j) {
    load_chain(j);
    for (std::size_t s = 0; s < shifts_.size(); ++s)
      for (Index f = 0; f < fields_; ++f) {
        std::fill(dq_.begin(), dq_.end(), 0.0);
        dq_[std::size_t(f * sites_ + radius_ + shifts_[s])] = 1;
        chain_.jacobian_action(q_.data(), dq_.data(), da_.data());
        for (Index g = 0; g < fields_; ++g) blocks[s](g + fields_ * f, j) = da_[std::size_t(g * sites_ + radius_)];
      }
  }
}

double WaveLattice::least_contact_overlap(Index& bond) const {
  const lrchain_lattice_contacts* contacts = chain_.kernels().displacement_contacts;
  double least = std::numeric_limits<double>::infinity();
  bond = -1;
  if (!contacts) return least;
  std::size_t terms = 0;
  for (int b = 0; b < contacts->bonds; ++b) terms += std::size_t(std::max(contacts->term_counts[b], 0));
  std::vector<double> offsets(std::size_t(contacts->bonds)), coefficients(terms);
  contacts->forms(parameters_.data(), offsets.data(), coefficients.data());
  std::size_t t = 0;
  for (int b = 0; b < contacts->bonds; ++b) {
    const int count = contacts->term_counts[b];
    if (count < 0) continue;
    for (Index j = 0; j < points_; ++j) {
      double s = offsets[std::size_t(b)];
      for (int i = 0; i < count; ++i) {
        const int m = contacts->shifts[t + std::size_t(i)];
        s += coefficients[t + std::size_t(i)] * shifted_[std::size_t(m + radius_)](contacts->variables[t + std::size_t(i)] * points_ + j);
      }
      if (s < least) {
        least = s;
        bond = b;
      }
    }
    t += std::size_t(count);
  }
  return least;
}

}  // namespace lrchain::sim::wave
