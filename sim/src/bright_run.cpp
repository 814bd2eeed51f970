// Bright breathers of any model file on its generated lattice (bright_run.hpp).
#include "lrchain/sim/bright_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <complex>
#include <numbers>

#include <fmt/format.h>

#include "lrchain/errors.hpp"
#include "lrchain/sim/energy.hpp"
#include "lrchain/sim/integrator.hpp"
#include "lrchain/sim/least_squares.hpp"
#include "lrchain/sim/model_lattice.hpp"
#include "lrchain/sim/strain_sites.hpp"
#include "model_lattice/driven_ends_lattice.hpp"

namespace lrchain::sim {

// M1, M2, a of the bright breather (eq:focus_app) from the model's coefficients at theta.
ModelBrightAnsatz::ModelBrightAnsatz(const Model& model, const lrchain_lattice_kernels& kernels, Index branch,
                                     double theta, std::optional<double> detuning, double n0, bool second_order)
    : nls_(coefficients_from_evaluators(model, branch, theta)), n0_(n0) {
  const std::string where = fmt::format("{} at theta = {} on branch {}", model.name(), theta,
                                        model.definition().branch_names.at(static_cast<std::size_t>(branch)));
  if (nls_.regime == Regime::singular)
    throw InvalidParameter("theta", "the NLS coefficients of " + where + " are singular (a resonance); no bright breather");
  if (nls_.regime != Regime::focusing)
    throw InvalidParameter("theta", fmt::format("the NLS of {} is not focusing (omega'' h_tilde = {:.6g} >= 0); bright "
                                                "breathers need omega'' h_tilde < 0 (lrchain regime map --model shows "
                                                "where)", where, nls_.curvature * nls_.h_tilde));
  if (!std::isfinite(n0)) throw InvalidParameter("n0", "must be a finite number");
  const double d = detuning.value_or(std::copysign(1e-4, nls_.h_tilde));
  if (!(std::isfinite(d) && d * nls_.h_tilde > 0))
    throw InvalidParameter("detuning", fmt::format("omega_b - omega must be nonzero with the sign of h_tilde = {:.6g}",
                                                   nls_.h_tilde));
  mode_ = bloch_mode(model, kernels, branch, theta);
  omega_b_ = nls_.omega + d;
  const double mu = nls_.omega - omega_b_;
  M2_ = std::sqrt(2.0 * (omega_b_ - nls_.omega) / nls_.h_tilde);
  a_ = std::sqrt(2.0 * mu / nls_.curvature);
  M1_ = model.definition().mean_flow ? nls_.lambda * std::sqrt(2.0 * nls_.curvature * mu) / std::abs(nls_.h_tilde) : 0.0;
  uses_second_order_ = second_order;
  if (second_order) {
    second_order_ = second_order_terms(model, branch, theta);
  } else {
    second_order_.second_harmonic.assign(mode_.kernel.size(), 0.0);
    second_order_.mean.assign(mode_.kernel.size(), 0.0);
    second_order_.kernel_gradient.assign(mode_.kernel.size(), 0.0);
  }
}

double ModelBrightAnsatz::period() const { return 2.0 * std::numbers::pi / omega_b_; }

void ModelBrightAnsatz::field(Index f, double n, double t, double& u, double& u_dot) const {
  const double c = nls_.group_velocity;
  const double z = a_ * (n - n0_ - c * t);
  const double e1 = std::exp(-std::abs(z));
  const double e = e1 * e1;
  const double th = std::copysign((1.0 - e) / (1.0 + e), z);
  const double sech = 2.0 * e1 / (1.0 + e);
  const std::complex<double> phase = std::polar(1.0, n * nls_.theta - omega_b_ * t);
  const std::complex<double> carrier = mode_.kernel[f] * phase;
  const std::complex<double> harmonic = second_order_.second_harmonic[f] * phase * phase;
  const std::complex<double> gradient = second_order_.kernel_gradient[f] * phase;
  const double A = M2_ * sech;  // the envelope |A|; dA/dn = -a tanh(z) A
  u = M1_ * th + 2.0 * A * carrier.real() + 2.0 * A * A * harmonic.real() + A * A * second_order_.mean[f] -
      2.0 * a_ * th * A * gradient.real();
  // d/dt [sech(z)^k e^{i k phase}] = k sech^k (c a tanh - i omega_b) e^{i k phase};
  // d/dt [tanh(z) sech(z) e^{i phase}] = sech (c a (tanh^2 - sech^2) - i omega_b tanh) e^{i phase}
  const std::complex<double> rate(c * a_ * th, -omega_b_), gradient_rate(c * a_ * (th * th - sech * sech), -omega_b_ * th);
  u_dot = -c * a_ * M1_ * sech * sech + 2.0 * A * (rate * carrier).real() + 4.0 * A * A * (rate * harmonic).real() +
          2.0 * c * a_ * th * A * A * second_order_.mean[f] - 2.0 * a_ * A * (gradient_rate * gradient).real();
}

void validate(const ModelBrightConfig& c) {
  if (!(c.theta > 0 && c.theta <= std::numbers::pi)) throw InvalidParameter("theta", "the carrier wavenumber must be in (0, pi]");
  check_half_width(c.N, model_bright_sites);
  if (!(c.periods > 0 && c.periods <= 1e6)) throw InvalidParameter("periods", "must be in (0, 1e6] (units of T_b)");
  if (!(c.sample_every > 0 && c.sample_every <= c.periods && c.periods / c.sample_every <= 1e6))
    throw InvalidParameter("sample_every", "must be in (0, periods] with at most 1e6 samples");
  if (!(std::isfinite(c.n0) && std::abs(c.n0) <= double(c.N)))
    throw InvalidParameter("n0", fmt::format("the initial centre must be in [-N, N] = [{}, {}] (sites = 2N + 1 = {})", -c.N,
                                             c.N, strain_site_count(c.N)));
  if (!(c.steps_per_period == 0 || (c.steps_per_period >= 8 && c.steps_per_period <= 1e4)))
    throw InvalidParameter("steps_per_period", "must be in [8, 1e4] (0: 24)");
  if (!(c.dt >= 0 && std::isfinite(c.dt))) throw InvalidParameter("dt", "must be a finite step > 0");
  if (!(c.tolerance >= 1e-14 && c.tolerance <= 1e-4)) throw InvalidParameter("tolerance", "must be in [1e-14, 1e-4]");
}

namespace {

// The fastest linear frequency of the lattice (all branches, theta in (0, pi]): sets the step.
double largest_linear_frequency(const lrchain_lattice_kernels& kernels, const std::vector<double>& parameters) {
  double largest = 0;
  for (int k = 1; k <= 16; ++k)
    for (double omega : branch_frequencies(kernels, parameters, std::numbers::pi * k / 16)) largest = std::max(largest, omega);
  return largest;
}

}  // namespace

ModelBrightResult run_bright(const Model& model, const lrchain_lattice_kernels& kernels,
                                   const ModelBrightConfig& c) {
  validate(c);
  const ModelBrightAnsatz ansatz(model, kernels, c.branch, c.theta, c.detuning, c.n0, c.second_order);
  const std::vector<double> parameters = lattice_parameters(model);
  ModelBrightResult r;
  r.mean_flow = model.definition().mean_flow;
  const std::size_t sites = std::size_t(2 * c.N + 1);  // n = -N..N
  const long first = -c.N;
  const CompiledLattice chain(kernels, parameters, sites, false, r.mean_flow ? LatticeForm::strain : LatticeForm::displacement);
  const std::size_t fields = chain.fields(), size = chain.positions();

  // Initial state from the ansatz: displacements at n = -N-1..N, then strain variables if needed.
  State s(2 * size, 0.0);
  std::vector<double> u(size + fields), v(size + fields);  // per field: sites + 1 (n = -N-1..N)
  const auto ansatz_displacements = [&](double t, double* U, double* V) {
    for (std::size_t f = 0; f < fields; ++f)
      for (std::size_t i = 0; i <= sites; ++i) ansatz.field(f, double(first - 1 + long(i)), t, U[f * (sites + 1) + i], V[f * (sites + 1) + i]);
  };
  ansatz_displacements(0.0, u.data(), v.data());
  for (std::size_t i = 0; i < sites; ++i)
    for (std::size_t f = 0; f < fields; ++f) {
      const std::size_t at = f * (sites + 1) + i + 1, base = i + 1;  // site first + i
      if (!r.mean_flow) {
        s[f * sites + i] = u[at];
        s[size + f * sites + i] = v[at];
      } else if (f == 0) {
        s[i] = u[base] - u[base - 1];
        s[size + i] = v[base] - v[base - 1];
      } else {
        s[f * sites + i] = u[at] - u[base];
        s[size + f * sites + i] = v[at] - v[base];
      }
    }

  const NlsCoefficients& nls = ansatz.nls();
  r.omega = nls.omega;
  r.omega_b = ansatz.omega_b();
  r.period = ansatz.period();
  r.group_velocity = nls.group_velocity;
  r.curvature = nls.curvature;
  r.h_tilde = nls.h_tilde;
  r.lambda = r.mean_flow ? nls.lambda : 0.0;
  r.M1 = ansatz.M1();
  r.M2 = ansatz.M2();
  r.inverse_width = ansatz.inverse_width();
  r.kernel = ansatz.mode().kernel;
  r.second_order = ansatz.second_order();
  r.uses_second_order = ansatz.uses_second_order();
  const double steps = c.steps_per_period > 0 ? c.steps_per_period : 24;
  r.dt = c.dt > 0 ? c.dt : 2 * std::numbers::pi / largest_linear_frequency(kernels, parameters) / steps;
  IntegratorOptions options;
  options.stepper = StepperKind::srkn11b;
  options.dt = std::min(r.dt, c.sample_every * r.period);
  r.ansatz_ends = c.ansatz_ends;
  if (c.ansatz_ends) {  // driven ends: not autonomous, so the adaptive rkf78 (as the resonant chain's run)
    options.stepper = StepperKind::rkf78;
    options.abs_tol = options.rel_tol = r.tolerance = c.tolerance;
  }

  const double t_end = c.periods * r.period, h = c.sample_every * r.period;
  std::vector<double> times;
  const long samples = long(std::floor(c.periods / c.sample_every + 1e-9));
  for (long k = 0; k <= samples; ++k) times.push_back(double(k) * h);
  if (t_end - times.back() > 1e-9 * t_end) times.push_back(t_end);

  auto& series = r.record.series;
  series.names = {"t"};
  for (std::size_t f = 0; f < fields; ++f) series.names.push_back(fmt::format("E_{}", f));
  series.names.insert(series.names.end(), {"energy", "X"});
  r.max_error.assign(fields, 0.0);
  r.final_error.assign(fields, 0.0);
  std::vector<double> scale(fields, 0.0), error(fields), lattice(size), ua(size + fields), va(size + fields), e(sites);
  std::vector<double> centre_t, centre_x;
  bool first_sample = true;
  // |energy| within end_zone_sites of either end over |energy| in all (energy densities of a
  // potential without a lower bound may be negative, so magnitudes).
  r.end_zone = std::min(end_zone_sites(e.size()), e.size() / 2);
  const auto end_energy_fraction = [zone = r.end_zone](const std::vector<double>& density) {
    double ends = 0, all = 0;
    for (std::size_t i = 0; i < density.size(); ++i) {
      all += std::abs(density[i]);
      if (i < zone || i >= density.size() - zone) ends += std::abs(density[i]);
    }
    return all > 0 ? ends / all : 0.0;
  };
  // x_f[i]: strain u_f[i] - u_f[i-1] (mean flow) or displacement u_f[i], sites i >= 1.
  const auto compared = [&](const double* U, std::size_t f, std::size_t i, std::size_t stride, std::size_t offset) {
    const double now = U[f * stride + i + offset];
    return r.mean_flow ? now - U[f * stride + i + offset - 1] : now;
  };
  const auto observe = [&](const State& x, double t) {
    if (c.progress) c.progress(std::min(1.0, t / t_end));
    chain.displacements_of(x.data(), lattice.data());
    ansatz_displacements(t, ua.data(), va.data());
    std::fill(error.begin(), error.end(), 0.0);
    for (std::size_t f = 0; f < fields; ++f)
      for (std::size_t i = 1; i < sites; ++i) {
        const double xl = compared(lattice.data(), f, i, sites, 0), xa = compared(ua.data(), f, i, sites + 1, 1);
        if (first_sample) scale[f] = std::max(scale[f], std::abs(xl));
        error[f] = std::max(error[f], std::abs(xl - xa));
      }
    series.data.push_back(t);
    for (std::size_t f = 0; f < fields; ++f) {
      error[f] /= scale[f] > 0 ? scale[f] : 1.0;
      r.max_error[f] = std::max(r.max_error[f], error[f]);
      r.final_error[f] = error[f];
      series.data.push_back(error[f]);
    }
    double energy = 0, X = 0;
    if (chain.has_energy()) {
      chain.energy_density(x.data(), x.data() + size, e.data());
      for (double v : e) energy += v;
      X = energy_centre(e, 100) + double(first);
      if (first_sample) r.energy0 = energy;
      const double near_ends = end_energy_fraction(e);
      r.max_end_energy_fraction = std::max(r.max_end_energy_fraction.value_or(0.0), near_ends);
      // (Emitting ends let the breather leave: there it passes the end zone without harm.)
      if (near_ends > end_energy_limit && !r.end_reached_at && !c.ansatz_ends) r.end_reached_at = t;
      r.max_energy_drift = std::max(r.max_energy_drift, std::abs(energy - r.energy0) / std::abs(r.energy0));
      centre_t.push_back(t);
      centre_x.push_back(X);
    }
    series.data.insert(series.data.end(), {energy, X});
    first_sample = false;
    if (t >= t_end * (1 - 1e-12)) {
      Snapshot snap;
      snap.t = t;
      snap.tag = "final";
      snap.names = {"n"};
      for (std::size_t f = 0; f < fields; ++f) {
        snap.names.push_back(fmt::format("x_{}", f));
        snap.names.push_back(fmt::format("x_{}_ansatz", f));
      }
      for (std::size_t i = 1; i < sites; ++i) {
        snap.data.push_back(double(first + long(i)));
        for (std::size_t f = 0; f < fields; ++f) {
          snap.data.push_back(compared(lattice.data(), f, i, sites, 0));
          snap.data.push_back(compared(ua.data(), f, i, sites + 1, 1));
        }
      }
      r.record.snapshots.push_back(std::move(snap));
    }
    return true;
  };
  const StepBoundaryHook poll_stop = [&c](const State&, double, double, const IntegrationStats&) {
    return !(c.stop && c.stop->load(std::memory_order_relaxed));
  };
  const auto start = std::chrono::steady_clock::now();
  if (c.ansatz_ends) {
    // The ghost sites beyond both ends in the lattice's variables, from the ansatz at time t.
    const auto end_motion = [&ansatz, &r, fields, first, sites](double t, double* left, double* right) {
      const auto variable = [&](std::size_t f, long n) {
        double u, u_dot, u0, u0_dot;
        ansatz.field(f, double(n), t, u, u_dot);
        if (!r.mean_flow) return u;
        ansatz.field(0, double(f == 0 ? n - 1 : n), t, u0, u0_dot);
        return u - u0;
      };
      const long g = long(DrivenEndsLattice::kGhostSites);
      for (std::size_t f = 0; f < fields; ++f)
        for (long k = 0; k < g; ++k) {
          left[f * std::size_t(g) + std::size_t(k)] = variable(f, first - g + k);
          right[f * std::size_t(g) + std::size_t(k)] = variable(f, first + long(sites) + k);
        }
    };
    const DrivenEndsLattice driven(kernels, parameters, sites, chain.form(), end_motion);
    r.stats = integrate_observed(driven, s, times, observe, options, poll_stop, 0, c.stop);
  } else {
    r.stats = integrate_observed(chain, s, times, observe, options, poll_stop, 0, c.stop);
  }
  if (r.stats.stopped) throw Interrupted(SIGINT, fmt::format("interrupted at t = {}", r.stats.t_reached));
  r.solve_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (r.stats.blew_up)
    throw NumericalFailure(fmt::format("{}: the bright-breather run blew up at t = {}", model.name(), r.stats.t_reached));
  if (chain.has_energy()) r.centre_speed = least_squares_slope(centre_t, centre_x);
  return r;
}

}  // namespace lrchain::sim
