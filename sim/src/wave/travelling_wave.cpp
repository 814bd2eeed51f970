// Exact periodic travelling waves by collocation and Gauss-Newton (travelling_wave.hpp).
#include "lrchain/sim/wave/travelling_wave.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "lrchain/errors.hpp"

namespace lrchain::sim::wave {

namespace {

// The linear wave A Re(K_f e^{i xi}) on H harmonics.
Eigen::VectorXd linear_profile(const BlochMode& mode, double amplitude, Index fields, const CollocationGrid& grid) {
  Eigen::VectorXd U(fields * grid.points);
  for (Index f = 0; f < fields; ++f)
    for (Index j = 0; j < grid.points; ++j)
      U(f * grid.points + j) = amplitude * (mode.kernel[std::size_t(f)] * std::polar(1.0, grid.phase(j))).real();
  return U;
}

// `profile` (fields x points) on H harmonics.
Eigen::VectorXd profile_on(const Eigen::VectorXd& profile, Index fields, Index harmonics) {
  const Index points = profile.size() / fields, N = 2 * harmonics + 1;
  if (points == N) return profile;
  Eigen::VectorXd out(fields * N);
  for (Index f = 0; f < fields; ++f) {
    const std::vector<double> r = resampled(profile.data() + f * points, points, harmonics);
    for (Index j = 0; j < N; ++j) out(f * N + j) = r[std::size_t(j)];
  }
  return out;
}

// Largest |2 c_k| over k > 2H/3 and every field, relative to A.
double tail_of(const Eigen::VectorXd& profile, Index fields, double amplitude) {
  const Index points = profile.size() / fields, H = (points - 1) / 2;
  double tail = 0;
  for (Index f = 0; f < fields; ++f) {
    const auto c = harmonics_of(profile.data() + f * points, points);
    for (Index k = (2 * H) / 3 + 1; k <= H; ++k) tail = std::max(tail, 2 * std::abs(c[std::size_t(k)]));
  }
  return tail / amplitude;
}

// The harmonic k in 2..min(H, 12) with k omega nearest a linear branch frequency at k theta.
void nearest_resonance(const WaveLattice& lattice, TravellingWave& w) {
  double best = std::numeric_limits<double>::infinity();
  for (Index k = 2; k <= std::min<Index>(w.harmonics, 12); ++k) {
    std::vector<double> omegas;
    try {
      omegas = branch_frequencies(lattice.kernels(), lattice.parameters(), double(k) * lattice.theta());
    } catch (const InvalidParameter&) {
      continue;  // k theta a multiple of 2 pi: a zero-frequency mode, no resonance with k omega > 0
    }
    for (double ob : omegas) {
      const double d = std::abs(double(k) * w.omega - ob) / w.omega;
      if (d < best) {
        best = d;
        w.resonance_harmonic = k;
      }
    }
  }
  w.resonance_distance = std::isfinite(best) ? best : 0.0;
}

// Gauss-Newton on one grid; returns the steps taken or throws NumericalFailure.
Index newton(WaveLattice& lattice, const CollocationGrid& grid, double amplitude, double omega_linear,
             const TravellingWaveOptions& o, Eigen::VectorXd& U, double& omega, double& residual) {
  const Index F = lattice.fields(), N = grid.points, n = F * N;
  const bool ti = lattice.translation_invariant();
  const Index rows = n + 2 + (ti ? 1 : 0);
  const double scale = omega_linear * omega_linear * amplitude;
  Eigen::VectorXd a, R(rows), step;
  Eigen::MatrixXd J(rows, n + 1);
  std::vector<Eigen::MatrixXd> blocks;
  Eigen::VectorXd cos1(N), sin1(N);
  for (Index j = 0; j < N; ++j) {
    cos1(j) = 2 * std::cos(grid.phase(j)) / double(N);
    sin1(j) = 2 * std::sin(grid.phase(j)) / double(N);
  }
  for (Index it = 0; it <= o.max_newton_steps; ++it) {
    lattice.prepare(grid, U);
    lattice.accelerations(a);
    for (Index f = 0; f < F; ++f)
      R.segment(f * N, N) = omega * omega * (grid.second_derivative * U.segment(f * N, N)) - a.segment(f * N, N);
    R(n) = sin1.dot(U.head(N));              // phase: no sin xi in U_0
    R(n + 1) = cos1.dot(U.head(N)) - amplitude;  // amplitude: A cos xi in U_0
    if (ti) R(n + 2) = U.head(N).mean();      // translation: mean of U_0 zero
    residual = R.head(n).cwiseAbs().maxCoeff() / scale;
    const double constraint = R.tail(rows - n).cwiseAbs().maxCoeff() / amplitude;
    if (!std::isfinite(residual) || !std::isfinite(omega)) break;
    if (residual <= o.newton_tolerance && constraint <= o.newton_tolerance) return it;
    if (it == o.max_newton_steps) break;
    lattice.jacobian_blocks(blocks);
    J.setZero();
    for (Index g = 0; g < F; ++g) J.block(g * N, g * N, N, N) = omega * omega * grid.second_derivative;
    for (std::size_t s = 0; s < blocks.size(); ++s) {
      const Eigen::MatrixXd& S = lattice.shift_matrix(lattice.shifts()[s]);
      for (Index g = 0; g < F; ++g)
        for (Index f = 0; f < F; ++f)
          J.block(g * N, f * N, N, N).noalias() -= blocks[s].row(g + F * f).transpose().asDiagonal() * S;
    }
    for (Index f = 0; f < F; ++f) J.block(f * N, n, N, 1) = 2 * omega * (grid.second_derivative * U.segment(f * N, N));
    J.block(n, 0, 1, N) = sin1.transpose();
    J.block(n + 1, 0, 1, N) = cos1.transpose();
    if (ti) J.block(n + 2, 0, 1, N).setConstant(1.0 / double(N));
    step = J.colPivHouseholderQr().solve(-R);
    U += step.head(n);
    omega += step(n);
  }
  throw NumericalFailure(fmt::format("Newton did not converge (residual {:.3g} after {} steps)", residual,
                                     o.max_newton_steps));
}

}  // namespace

std::vector<std::complex<double>> wave_harmonics(const TravellingWave& wave, Index field) {
  const Index points = 2 * wave.harmonics + 1;
  return harmonics_of(wave.profile.data() + field * points, points);
}

TravellingWave solve_travelling_wave(WaveLattice& lattice, const BlochMode& mode, double amplitude,
                                     const TravellingWaveOptions& o, const TravellingWave* seed) {
  const Index F = lattice.fields();
  TravellingWave w;
  w.theta = lattice.theta();
  w.amplitude = amplitude;
  w.omega_linear = mode.omega;
  w.translation_invariant = lattice.translation_invariant();
  w.harmonics = seed ? std::max(seed->harmonics, o.initial_harmonics) : o.initial_harmonics;
  Eigen::VectorXd U;
  if (seed) {
    U = profile_on(seed->profile, F, w.harmonics) * (amplitude / seed->amplitude);
    const double r = amplitude / seed->amplitude;
    w.omega = seed->omega + (seed->omega - seed->omega_linear) * (r * r - 1);  // the shift grows like A^2
  } else {
    U = linear_profile(mode, amplitude, F, CollocationGrid(w.harmonics));
    w.omega = mode.omega;
  }
  for (;;) {
    const CollocationGrid grid(w.harmonics);
    try {
      w.newton_steps = newton(lattice, grid, amplitude, mode.omega, o, U, w.omega, w.residual);
    } catch (const NumericalFailure& e) {
      w.profile = U;
      lattice.prepare(grid, U);
      Index bond = -1;
      const double overlap = lattice.least_contact_overlap(bond);
      if (overlap < 0)
        throw NumericalFailure(fmt::format("no travelling wave at theta = {}, A = {}: Newton did not converge and "
                                           "contact {} opens along its last iterate (least overlap {:.3g}): "
                                           "the wave loses contact",
                                           w.theta, amplitude, lattice.kernels().displacement_contacts->names[bond], overlap));
      nearest_resonance(lattice, w);
      throw NumericalFailure(fmt::format("no travelling wave at theta = {}, A = {} on {} harmonics: {}; nearest "
                                         "harmonic resonance: {} omega within {:.3g} omega of a linear frequency at "
                                         "{} theta",
                                         w.theta, amplitude, w.harmonics, e.what(), w.resonance_harmonic,
                                         w.resonance_distance, w.resonance_harmonic));
    }
    w.tail = tail_of(U, F, amplitude);
    if (w.tail <= o.tail_tolerance) break;
    if (w.harmonics >= o.max_harmonics)
      throw NumericalFailure(fmt::format("no resolved travelling wave at theta = {}, A = {}: its harmonics do not "
                                         "decay below {} (tail {:.3g}) within {} harmonics",
                                         w.theta, amplitude, o.tail_tolerance, w.tail, o.max_harmonics));
    w.harmonics = std::min(2 * w.harmonics, o.max_harmonics);
    U = profile_on(U, F, w.harmonics);
  }
  w.profile = U;
  Index bond = -1;
  const double overlap = lattice.least_contact_overlap(bond);
  if (std::isfinite(overlap)) {
    w.least_contact_overlap = overlap;
    if (overlap < 0)
      throw NumericalFailure(fmt::format("no travelling wave at theta = {}, A = {}: contact {} opens along the wave "
                                         "(least overlap {:.3g})",
                                         w.theta, amplitude, lattice.kernels().displacement_contacts->names[bond], overlap));
  }
  nearest_resonance(lattice, w);
  return w;
}

WaveBranch continue_travelling_wave(WaveLattice& lattice, const BlochMode& mode, const std::vector<double>& amplitudes,
                                    const TravellingWaveOptions& options) {
  WaveBranch branch;
  for (double A : amplitudes) {
    try {
      branch.waves.push_back(
          solve_travelling_wave(lattice, mode, A, options, branch.waves.empty() ? nullptr : &branch.waves.back()));
    } catch (const NumericalFailure& e) {
      branch.stopped = e.what();
      branch.stopped_at = A;
      break;
    }
  }
  return branch;
}

void profile_at(const std::vector<std::complex<double>>& c, double xi, double& u, double& du) {
  u = c[0].real();
  du = 0;
  for (std::size_t k = 1; k < c.size(); ++k) {
    const std::complex<double> e = c[k] * std::polar(1.0, double(k) * xi);
    u += 2 * e.real();
    du -= 2 * double(k) * e.imag();
  }
}

}  // namespace lrchain::sim::wave
