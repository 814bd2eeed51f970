// Exact standing waves on a ring by collocation in time and Gauss-Newton (standing_wave.hpp).
#include "lrchain/sim/wave/standing_wave.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <limits>
#include <random>

#include <fmt/format.h>

#include "lrchain/errors.hpp"

namespace lrchain::sim::wave {

namespace {

Index wrap(Index n, Index sites) { return ((n % sites) + sites) % sites; }

// q -> R q with (R q)_f[n] = sign q_f[offset_f - n].
void reflect(const ReflectionSymmetry& r, Index fields, Index sites, const double* q, double* out) {
  for (Index f = 0; f < fields; ++f)
    for (Index n = 0; n < sites; ++n)
      out[f * sites + n] = r.sign * q[f * sites + wrap(r.offsets[std::size_t(f)] - n, sites)];
}

// The least overlap s_n = offset + sum coefficient q[variable][n + shift] of the ring's one-sided
// contacts at positions q (infinity without contacts).
double least_overlap(const CompiledLattice& ring, const Eigen::VectorXd& q) {
  const std::vector<double>& parameters = ring.parameters();
  const lrchain_lattice_contacts* contacts = ring.kernels().displacement_contacts;
  double least = std::numeric_limits<double>::infinity();
  if (!contacts) return least;
  std::size_t terms = 0;
  for (int b = 0; b < contacts->bonds; ++b) terms += std::size_t(std::max(contacts->term_counts[b], 0));
  std::vector<double> offsets(std::size_t(contacts->bonds)), coefficients(terms);
  contacts->forms(parameters.data(), offsets.data(), coefficients.data());
  const Index N = ring.sites();
  std::size_t t = 0;
  for (int b = 0; b < contacts->bonds; ++b) {
    const int count = contacts->term_counts[b];
    if (count < 0) continue;
    for (Index n = 0; n < N; ++n) {
      double s = offsets[std::size_t(b)];
      for (int i = 0; i < count; ++i)
        s += coefficients[t + std::size_t(i)] *
             q(contacts->variables[t + std::size_t(i)] * N + wrap(n + contacts->shifts[t + std::size_t(i)], N));
      least = std::min(least, s);
    }
    t += std::size_t(count);
  }
  return least;
}

// Largest |c_k| with k > 2H/3 over every site, relative to A.
double cosine_tail(const Eigen::MatrixXd& c, double amplitude) {
  const Index H = c.cols() - 1, from = 2 * H / 3 + 1;
  return from > H ? 0.0 : c.rightCols(H - from + 1).cwiseAbs().maxCoeff() / amplitude;
}

// Gauss-Newton at fixed H from `c`, `omega`; returns the steps taken, or -1 when it did not converge.
Index newton(CompiledLattice& ring, double theta, double amplitude, bool mean_fixed, double scale,
             const StandingWaveOptions& o, Eigen::MatrixXd& c, double& omega, double& residual) {
  const Index P = ring.positions(), N = ring.sites(), H = c.cols() - 1, unknowns = P * (H + 1) + 1;
  const Index rows = P * (H + 1) + 2 + (mean_fixed ? 1 : 0);
  Eigen::MatrixXd cosines(H + 1, H + 1);  // cos(k pi i / H): row i, column k
  for (Index i = 0; i <= H; ++i)
    for (Index k = 0; k <= H; ++k) cosines(i, k) = std::cos(double(k * i) * std::numbers::pi / double(H));
  Eigen::MatrixXd jacobian(rows, unknowns), blocks(P, P);
  Eigen::VectorXd r(rows), q(P), a(P), unit = Eigen::VectorXd::Zero(P), column(P), k2(H + 1);
  for (Index k = 0; k <= H; ++k) k2(k) = double(k * k);
  for (Index step = 0; step <= o.max_newton_steps; ++step) {
    jacobian.setZero();
    // omega^2 u''(t_i) - a(u(t_i)) = -omega^2 sum_k k^2 c_k cos(k tau_i) - a, per position p and time i.
    for (Index i = 0; i <= H; ++i) {
      q = c * cosines.row(i).transpose();
      ring.acceleration(q.data(), a.data());
      const Eigen::VectorXd curvature = c * (cosines.row(i).transpose().cwiseProduct(k2));
      for (Index p = 0; p < P; ++p) r(i * P + p) = -omega * omega * curvature(p) - a(p);
      for (Index p = 0; p < P; ++p) {
        unit(p) = 1;
        ring.jacobian_action(q.data(), unit.data(), column.data());
        unit(p) = 0;
        blocks.col(p) = column;
      }
      for (Index k = 0; k <= H; ++k) {
        jacobian.block(i * P, k * P, P, P) = -cosines(i, k) * blocks;
        jacobian.block(i * P, k * P, P, P).diagonal().array() -= omega * omega * k2(k) * cosines(i, k);
      }
      jacobian.block(i * P, P * (H + 1), P, 1) = -2 * omega * curvature;
    }
    // The first field's cos(theta n) and sin(theta n) parts of cos(omega t): A and 0; its mean: 0.
    const Index base = P * (H + 1);
    r(base) = -amplitude;
    r(base + 1) = 0;
    for (Index n = 0; n < N; ++n) {
      const double cn = 2 * std::cos(theta * double(n)) / double(N), sn = 2 * std::sin(theta * double(n)) / double(N);
      r(base) += cn * c(n, 1);
      r(base + 1) += sn * c(n, 1);
      jacobian(base, P + n) = cn;
      jacobian(base + 1, P + n) = sn;
      if (mean_fixed) jacobian(base + 2, n) = 1.0 / double(N);
    }
    if (mean_fixed) r(base + 2) = c.col(0).head(N).mean();
    residual = r.cwiseAbs().maxCoeff() / scale;
    if (!std::isfinite(residual)) return -1;
    if (residual < o.newton_tolerance) return step;
    if (step == o.max_newton_steps) break;
    const Eigen::VectorXd dx = jacobian.colPivHouseholderQr().solve(r);
    for (Index k = 0; k <= H; ++k) c.col(k) -= dx.segment(k * P, P);
    omega -= dx(P * (H + 1));
  }
  return -1;
}

}  // namespace

std::optional<ReflectionSymmetry> reflection_symmetry(const CompiledLattice& ring) {
  const Index F = ring.fields(), N = ring.sites(), P = ring.positions();
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> small(-1e-2, 1e-2);
  std::vector<double> q(static_cast<std::size_t>(P));
  std::vector<double> rq = q, a = q, ra = q, a_of_rq = q;
  for (double& x : q) x = small(random);
  ring.acceleration(q.data(), a.data());
  const double size = std::max(1e-300, std::abs(*std::max_element(a.begin(), a.end(), [](double x, double y) {
    return std::abs(x) < std::abs(y);
  })));
  Index combinations = 1;
  for (Index f = 1; f < F; ++f) combinations *= 3;
  for (int sign : {1, -1})
    for (Index k = 0; k < combinations; ++k) {
      ReflectionSymmetry r{sign, std::vector<int>(std::size_t(F), 0)};
      for (Index f = 1, rest = k; f < F; ++f, rest /= 3) r.offsets[std::size_t(f)] = int(rest % 3) - 1;
      reflect(r, F, N, q.data(), rq.data());
      ring.acceleration(rq.data(), a_of_rq.data());
      reflect(r, F, N, a.data(), ra.data());
      double differs = 0;
      for (Index p = 0; p < P; ++p) differs = std::max(differs, std::abs(a_of_rq[std::size_t(p)] - ra[std::size_t(p)]));
      if (differs < 1e-10 * size) return r;
    }
  return std::nullopt;
}

void standing_positions(const StandingWave& wave, Index sites, double t, Eigen::VectorXd& q) {
  const Index F = wave.coefficients.rows() / wave.sites, H = wave.harmonics;
  q.resize(F * sites);
  for (Index f = 0; f < F; ++f)
    for (Index n = 0; n < sites; ++n) {
      double u = 0;
      for (Index k = 0; k <= H; ++k)
        u += wave.coefficients(f * wave.sites + n % wave.sites, k) * std::cos(double(k) * wave.omega * t);
      q(f * sites + n) = u;
    }
}

StandingWave solve_standing_wave(CompiledLattice& ring, const BlochMode& mode, double theta, double amplitude,
                                 const StandingWaveOptions& o, const StandingWave* seed) {
  const Index F = ring.fields(), N = ring.sites(), P = ring.positions();
  StandingWave w;
  w.theta = theta;
  w.amplitude = amplitude;
  w.omega_linear = mode.omega;
  w.sites = N;
  Index H = seed ? seed->harmonics : o.initial_harmonics;
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(P, H + 1);
  double omega = mode.omega;
  if (seed) {
    c = seed->coefficients * (amplitude / seed->amplitude);
    omega = seed->omega;
  } else {
    for (Index f = 0; f < F; ++f)
      for (Index n = 0; n < N; ++n)
        c(f * N + n, 1) = amplitude * (mode.kernel[std::size_t(f)] * std::polar(1.0, theta * double(n))).real();
  }
  // A uniform displacement of every field changes no acceleration: fix the first field's mean.
  Eigen::VectorXd q = Eigen::VectorXd::Constant(P, 0.0), a0(P), a1(P);
  ring.acceleration(q.data(), a0.data());
  q.setConstant(1e-3);
  ring.acceleration(q.data(), a1.data());
  const bool mean_fixed = (a1 - a0).cwiseAbs().maxCoeff() < 1e-12;
  const double scale = mode.omega * mode.omega * amplitude;
  for (;;) {
    double residual = 0;
    const Index steps = newton(ring, theta, amplitude, mean_fixed, scale, o, c, omega, residual);
    if (steps < 0)
      throw NumericalFailure(fmt::format("no standing wave at theta = {}, A = {}: Newton did not converge in {} steps "
                                         "(residual {:.3g}, H = {})",
                                         theta, amplitude, o.max_newton_steps, residual, H));
    w.newton_steps += steps;
    w.residual = residual;
    w.tail = cosine_tail(c, amplitude);
    w.omega = omega;
    w.harmonics = H;
    w.coefficients = c;
    if (ring.kernels().displacement_contacts) {  // a one-sided contact that opens: the clamped force has no smooth orbit
      double least = std::numeric_limits<double>::infinity();
      for (Index i = 0; i <= 4 * H; ++i) {
        standing_positions(w, N, std::numbers::pi * double(i) / (4 * double(H) * omega), q);
        least = std::min(least, least_overlap(ring, q));
      }
      w.least_contact_overlap = least;
      if (least < 0)
        throw NumericalFailure(fmt::format("no standing wave at theta = {}, A = {}: a one-sided contact opens along "
                                           "the wave (least overlap {:.3g}): the wave loses contact",
                                           theta, amplitude, least));
    }
    if (w.tail <= o.tail_tolerance) break;
    if (2 * H > o.max_harmonics)
      throw NumericalFailure(fmt::format("no standing wave at theta = {}, A = {}: its harmonics do not decay within "
                                         "max_harmonics = {} (tail {:.3g})",
                                         theta, amplitude, o.max_harmonics, w.tail));
    Eigen::MatrixXd wider = Eigen::MatrixXd::Zero(P, 2 * H + 1);
    wider.leftCols(H + 1) = c;
    c = std::move(wider);
    H *= 2;
  }
  return w;
}

StandingWaveBranch continue_standing_wave(CompiledLattice& ring, const BlochMode& mode, double theta,
                                          const std::vector<double>& amplitudes, const StandingWaveOptions& o) {
  StandingWaveBranch b;
  for (double amplitude : amplitudes) {
    try {
      b.waves.push_back(solve_standing_wave(ring, mode, theta, amplitude, o, b.waves.empty() ? nullptr : &b.waves.back()));
    } catch (const NumericalFailure& e) {
      b.stopped = e.what();
      b.stopped_at = amplitude;
      break;
    }
  }
  return b;
}

}  // namespace lrchain::sim::wave
