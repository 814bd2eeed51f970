// The checked evaluation of a loaded model's NLS coefficients (lrchain/coefficient_check.hpp):
// c and omega'' against omega's derivatives from det M alone, h and h_tilde against rounding noise,
// else the limit of symmetric nearby evaluations (Richardson extrapolation in the offset squared),
// else refused as singular.
#include "coefficient_check.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "lrchain/coefficient_check.hpp"
#include "lrchain/half_angle.hpp"
#include "lrchain/model.hpp"

namespace lrchain {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kDerivativeStep = 2e-3;  // theta offset of the central differences of omega^2 (and half of it)
constexpr double kNoiseStep = 1e-6;       // theta offset of the second difference that measures h's rounding noise
constexpr double kNoiseTolerance = 1e-7;  // relative second difference above which h counts as noisy (if not smooth)
constexpr double kLimitStep = 0.02;       // largest offset of the limit evaluation (then halved three times)
constexpr int kLimitLevels = 4;
constexpr double kLimitTolerance = 1e-6;  // relative change of the last two Richardson levels accepted

// Value of sum_k w[k] x^k and its derivative (Horner).
void polynomial_and_slope(const double* w, Index degree, double x, double& p, double& dp) noexcept {
  p = w[degree];
  dp = 0;
  for (Index k = degree - 1; k >= 0; --k) {
    dp = dp * x + p;
    p = p * x + w[k];
  }
}

// omega^2 of `branch` at theta from det M: closed form for degree <= 2, else Newton's method from
// the branch's omega^2 nearby (accepted within a quarter of the gap to the neighbouring roots,
// else all roots by Durand-Kerner). Any finite value (the acoustic branch may reach 0 nearby).
bool branch_omega_squared(const ModelDefinition& d, const double* q, Index branch, double theta, double guess,
                          double gap, double& w2) noexcept {
  double sh, ch;
  detail::half_angle_sincos(0.5 * theta, sh, ch);
  double w[kMaxModelDegree + 1], roots[kMaxModelDegree];
  d.evaluators.evaluate_dispersion(4.0 * sh * sh, 2.0 * sh * ch, q, w);
  if (d.degree > 2) {
    double x = guess;
    for (int iteration = 0; iteration < 40; ++iteration) {
      double p, dp;
      polynomial_and_slope(w, d.degree, x, p, dp);
      if (dp == 0.0) break;
      const double step = p / dp;
      x -= step;
      if (std::abs(step) <= 4.0 * kEps * std::abs(x)) {
        if (std::abs(x - guess) <= 0.25 * gap) {
          w2 = x;
          return std::isfinite(x);
        }
        break;
      }
    }
  }
  if (!omega_squared_roots(w, d.degree, roots)) return false;
  w2 = roots[branch];
  return std::isfinite(w2);
}

// Distance from the branch's omega^2 at theta to its neighbouring roots (infinite for degree <= 2:
// those use the closed form).
double root_gap(const ModelDefinition& d, const double* q, Index branch, double theta) noexcept {
  if (d.degree <= 2) return std::numeric_limits<double>::infinity();
  double sh, ch;
  detail::half_angle_sincos(0.5 * theta, sh, ch);
  double w[kMaxModelDegree + 1], roots[kMaxModelDegree];
  d.evaluators.evaluate_dispersion(4.0 * sh * sh, 2.0 * sh * ch, q, w);
  if (!omega_squared_roots(w, d.degree, roots)) return 0;
  double gap = std::numeric_limits<double>::infinity();
  if (branch > 0) gap = std::min(gap, roots[branch] - roots[branch - 1]);
  if (branch + 1 < d.degree) gap = std::min(gap, roots[branch + 1] - roots[branch]);
  return gap;
}

// The coefficients a limit extrapolates, as pointers to members.
constexpr double NlsCoefficients::* kLimitFields[] = {
    &NlsCoefficients::group_velocity, &NlsCoefficients::curvature, &NlsCoefficients::gamma,
    &NlsCoefficients::beta,           &NlsCoefficients::h,         &NlsCoefficients::lambda,
    &NlsCoefficients::h_tilde,        &NlsCoefficients::h_tilde_numerator, &NlsCoefficients::nonresonance1,
    &NlsCoefficients::nonresonance2};
constexpr int kLimitFieldCount = sizeof kLimitFields / sizeof kLimitFields[0];

// h and h_tilde at theta +- step, theta +- 2 step: false if a nearby point has no coefficients.
// Second differences of rounding noise do not scale as step^2: noisy unless each doubling of the
// step multiplies the second difference by about 4 (smooth, e.g. near a true pole of h).
bool noisy_h(const ModelDefinition& d, const double* q, Index branch, const NlsCoefficients& c) noexcept {
  const double NlsCoefficients::* fields[] = {&NlsCoefficients::h, &NlsCoefficients::h_tilde};
  double second[3][2];
  for (int level = 0; level < 3; ++level) {
    const double step = kNoiseStep * double(1 << level);
    NlsCoefficients plus, minus;
    if (!detail::unchecked_model_coefficients(d, q, branch, c.theta + step, plus) ||
        !detail::unchecked_model_coefficients(d, q, branch, c.theta - step, minus))
      return false;
    bool small = true;
    for (int f = 0; f < 2; ++f) {
      const double centre = c.*fields[f];
      second[level][f] = plus.*fields[f] - 2.0 * centre + minus.*fields[f];
      const double size = std::abs(centre) + std::abs(plus.*fields[f]) + std::abs(minus.*fields[f]);
      if (std::isfinite(centre) && !(std::abs(second[level][f]) <= kNoiseTolerance * size)) small = false;
    }
    if (level == 0 && small) return false;  // the common case: one extra pair of evaluations
  }
  for (int f = 0; f < 2; ++f) {
    if (!std::isfinite(c.*fields[f])) continue;
    for (int level = 1; level < 3; ++level) {
      const double ratio = second[level][f] / second[level - 1][f];
      if (!(ratio > 3.0 && ratio < 5.3)) return true;
    }
  }
  return false;
}

// c replaced by the limit of the symmetric means of unchecked evaluations at theta +- kLimitStep / 2^k,
// extrapolated in the offset squared; false when a nearby point fails or the levels do not agree.
bool limit_coefficients(const ModelDefinition& d, const double* q, Index branch, NlsCoefficients& c) noexcept {
  double table[kLimitLevels][kLimitFieldCount];
  for (int k = 0; k < kLimitLevels; ++k) {
    const double step = kLimitStep / double(1 << k);
    NlsCoefficients plus, minus;
    if (!detail::unchecked_model_coefficients(d, q, branch, c.theta + step, plus) ||
        !detail::unchecked_model_coefficients(d, q, branch, c.theta - step, minus) ||
        plus.regime == Regime::singular || minus.regime == Regime::singular)
      return false;
    for (int f = 0; f < kLimitFieldCount; ++f) table[k][f] = 0.5 * (plus.*kLimitFields[f] + minus.*kLimitFields[f]);
  }
  NlsCoefficients limit = c;
  for (int f = 0; f < kLimitFieldCount; ++f) {
    double row[kLimitLevels], previous_diagonal = 0, largest = 0;
    for (int k = 0; k < kLimitLevels; ++k) {
      row[k] = table[k][f];
      largest = std::max(largest, std::abs(row[k]));
    }
    // Neville-Richardson in place: after pass j, row[k] (k >= j) eliminates the offset^2j terms.
    for (int j = 1; j < kLimitLevels; ++j) {
      previous_diagonal = row[j - 1];
      const double factor = double(1 << (2 * j)) - 1.0;
      for (int k = kLimitLevels - 1; k >= j; --k) row[k] += (row[k] - row[k - 1]) / factor;
    }
    const double value = row[kLimitLevels - 1];
    if (std::isnan(c.*kLimitFields[f]) && std::isnan(value)) continue;  // e.g. lambda of an on-site model
    if (!(std::abs(value - previous_diagonal) <= kLimitTolerance * std::abs(value) + 1e-9 * largest)) return false;
    limit.*kLimitFields[f] = value;
  }
  const double product = limit.curvature * limit.h_tilde;
  limit.regime = product < 0 ? Regime::focusing : product > 0 ? Regime::defocusing : Regime::degenerate;
  limit.evaluation = CoefficientEvaluation::limit;
  c = limit;
  return true;
}

// Every coefficient but omega (and theta) NaN, the regime singular, the evaluation refused.
void refuse(NlsCoefficients& c) noexcept {
  for (const auto field : kLimitFields) c.*field = std::numeric_limits<double>::quiet_NaN();
  c.regime = Regime::singular;
  c.evaluation = CoefficientEvaluation::refused;
}

}  // namespace

bool branch_derivatives(const ModelDefinition& d, const double* q, Index branch, double theta, double omega,
                        BranchDerivatives& out) noexcept {
  const double W0 = omega * omega;
  const double gap = root_gap(d, q, branch, theta);
  double W[2][2];  // [step, step / 2][+, -]
  for (int level = 0; level < 2; ++level)
    for (int side = 0; side < 2; ++side) {
      const double offset = (side ? -1.0 : 1.0) * kDerivativeStep / double(1 << level);
      if (!branch_omega_squared(d, q, branch, theta + offset, W0, gap, W[level][side])) return false;
    }
  double first[2], second[2], largest = std::abs(W0);
  for (int level = 0; level < 2; ++level) {
    const double h = kDerivativeStep / double(1 << level);
    first[level] = (W[level][0] - W[level][1]) / (2.0 * h);
    second[level] = (W[level][0] - 2.0 * W0 + W[level][1]) / (h * h);
    largest = std::max({largest, std::abs(W[level][0]), std::abs(W[level][1])});
  }
  const double h = 0.5 * kDerivativeStep;
  const double W1 = (4.0 * first[1] - first[0]) / 3.0, W2 = (4.0 * second[1] - second[0]) / 3.0;
  const double W1_error = std::abs(first[1] - first[0]) / 3.0 + 16.0 * kEps * largest / h;
  const double W2_error = std::abs(second[1] - second[0]) / 3.0 + 64.0 * kEps * largest / (h * h);
  // omega = sqrt(W): c = W' / (2 omega), omega'' = (W'' - 2 c^2) / (2 omega).
  out.group_velocity = W1 / (2.0 * omega);
  out.group_velocity_error = W1_error / (2.0 * omega);
  out.curvature = (W2 - 2.0 * out.group_velocity * out.group_velocity) / (2.0 * omega);
  out.curvature_error = (W2_error + 4.0 * std::abs(out.group_velocity) * out.group_velocity_error) / (2.0 * omega);
  return std::isfinite(out.curvature) && std::isfinite(out.curvature_error);
}

bool agrees_with_derivatives(const NlsCoefficients& c, const BranchDerivatives& d) noexcept {
  const double tolerance = 1e-7;
  const double c_scale = std::abs(d.group_velocity) + c.omega;
  const double curvature_scale = std::abs(d.curvature) + c_scale;
  return std::abs(c.group_velocity - d.group_velocity) <= tolerance * c_scale + 10.0 * d.group_velocity_error &&
         std::abs(c.curvature - d.curvature) <= tolerance * curvature_scale + 10.0 * d.curvature_error;
}

std::string_view singular_reason(const NlsCoefficients& c) {
  if (c.evaluation == CoefficientEvaluation::refused)
    return "removable singularity of the derived expressions (0/0 at or near this wavenumber): their c or omega'' "
           "disagree with the derivatives of omega from det M, or h loses its digits, and their limit from nearby "
           "wavenumbers did not converge";
  if (c.regime == Regime::singular) return "a non-resonance condition is violated (eq:nonresonance1, eq:nonresonance2): h has a pole";
  return {};
}

namespace detail {

void check_or_limit(const ModelDefinition& d, const double* q, Index branch, NlsCoefficients& c) noexcept {
  BranchDerivatives derivatives;
  const bool have_derivatives = branch_derivatives(d, q, branch, c.theta, c.omega, derivatives);
  const bool derivatives_agree = !have_derivatives || agrees_with_derivatives(c, derivatives);
  if (derivatives_agree && (c.regime == Regime::singular || !noisy_h(d, q, branch, c))) return;
  if (limit_coefficients(d, q, branch, c) && (!have_derivatives || agrees_with_derivatives(c, derivatives))) return;
  refuse(c);
}

}  // namespace detail
}  // namespace lrchain
