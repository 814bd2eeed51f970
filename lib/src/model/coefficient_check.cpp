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
constexpr double kScreenStep = 1e-8;      // theta offset of the screen's second evaluation
constexpr double kScreenTolerance = 1e-6; // relative change over kScreenStep above which the full check runs
constexpr double kConsistencyTolerance = 1e-10;  // h_tilde two ways (h_tilde_consistent), relative to h's terms
constexpr double kImplicitStep = 1e-4;    // theta offset of the hot path's differences of det M at fixed omega^2
constexpr double kNoiseStep = 1e-6;       // theta offset of the second differences that measure rounding noise
constexpr double kNoiseTolerance = 1e-7;  // relative second difference above which a field counts as noisy (if not smooth)
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

// sum_k w[k] x^k, its first and second derivative, and sum_k |w[k] x^k| (the size of its rounding).
void polynomial_derivatives(const double* w, Index degree, double x, double& p, double& dp, double& ddp,
                            double& size) noexcept {
  p = w[degree];
  dp = ddp = 0;
  size = std::abs(w[degree]);
  const double ax = std::abs(x);
  for (Index k = degree - 1; k >= 0; --k) {
    ddp = ddp * x + 2.0 * dp;
    dp = dp * x + p;
    p = p * x + w[k];
    size = size * ax + std::abs(w[k]);
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

// The coefficients a limit extrapolates, as pointers to members (what refuse() sets to NaN).
constexpr double NlsCoefficients::* kLimitFields[] = {
    &NlsCoefficients::group_velocity, &NlsCoefficients::curvature, &NlsCoefficients::gamma,
    &NlsCoefficients::beta,           &NlsCoefficients::nonresonance1, &NlsCoefficients::nonresonance2,
    &NlsCoefficients::h,              &NlsCoefficients::lambda,        &NlsCoefficients::h_tilde,
    &NlsCoefficients::h_tilde_numerator};

// The quantities the check tests for lost digits and the limit extrapolates: c, omega'', gamma,
// beta, the non-resonance values, and h, lambda, h_tilde times the non-resonance values they are
// divided by (h nonresonance1, lambda nonresonance2, h_tilde_numerator): smooth across the true
// poles of a violated non-resonance condition, so that only a 0/0 of the expressions (or a pole of
// another cause) shows. The first kPoleFieldStart can have no pole.
constexpr int kCheckedFieldCount = 9;
constexpr int kPoleFieldStart = 6;
void checked_fields(const NlsCoefficients& c, double (&v)[kCheckedFieldCount]) noexcept {
  v[0] = c.group_velocity;
  v[1] = c.curvature;
  v[2] = c.gamma;
  v[3] = c.beta;
  v[4] = c.nonresonance1;
  v[5] = c.nonresonance2;
  v[6] = c.h * c.nonresonance1;
  v[7] = c.lambda * c.nonresonance2;
  v[8] = c.h_tilde_numerator;
}

// |a - b| small against |a| + |b| (both NaN: equal, e.g. lambda of an on-site model).
bool relatively_close(double a, double b, double tolerance) noexcept {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::abs(a - b) <= tolerance * (std::abs(a) + std::abs(b));
}

// Second differences of a field at steps s, 2s, 4s: smooth when the smallest is small against the
// values, or when each doubling of the step multiplies it by 3..80 (a smooth function whose
// expansion starts at step^2, step^4 or step^6: e.g. h ~ theta^4 at theta = 0). Rounding noise
// (the digits a 0/0 of the expressions loses) does neither.
bool smooth_field(const double (&second)[3], const double (&size)[3], double centre) noexcept {
  if (!std::isfinite(centre)) return true;  // NaN by design (on-site lambda, a violated non-resonance)
  if (std::abs(second[0]) <= kNoiseTolerance * size[0]) return true;
  for (int level = 1; level < 3; ++level) {
    const double ratio = second[level] / second[level - 1];
    if (!(ratio > 3.0 && ratio < 80.0)) return false;
  }
  return true;
}

// Every field smooth at theta (second differences at theta +- kNoiseStep 2^k); false if a nearby
// point has no coefficients or a field's second differences look like rounding noise.
bool smooth_at(const ModelDefinition& d, const double* q, Index branch, const NlsCoefficients& c) noexcept {
  double second[3][kCheckedFieldCount], size[3][kCheckedFieldCount], centre[kCheckedFieldCount];
  checked_fields(c, centre);
  for (int level = 0; level < 3; ++level) {
    const double step = kNoiseStep * double(1 << level);
    NlsCoefficients plus, minus;
    if (!detail::unchecked_model_coefficients(d, q, branch, c.theta + step, plus) ||
        !detail::unchecked_model_coefficients(d, q, branch, c.theta - step, minus))
      return false;
    double p[kCheckedFieldCount], m[kCheckedFieldCount];
    checked_fields(plus, p);
    checked_fields(minus, m);
    for (int f = 0; f < kCheckedFieldCount; ++f) {
      second[level][f] = p[f] - 2.0 * centre[f] + m[f];
      size[level][f] = std::abs(centre[f]) + std::abs(p[f]) + std::abs(m[f]);
    }
  }
  for (int f = 0; f < kCheckedFieldCount; ++f) {
    const double s[3] = {second[0][f], second[1][f], second[2][f]}, z[3] = {size[0][f], size[1][f], size[2][f]};
    if (!smooth_field(s, z, centre[f])) return false;
  }
  return true;
}

// How the limit of one field from symmetric nearby evaluations came out.
enum class FieldLimit { converged, pole, failed };

// Neville-Richardson extrapolation of the symmetric means mean[k] (offset kLimitStep / 2^k) in the
// offset squared; side[k] = the larger |value| of the two sides. A pole: the sides grow at least
// 1.8-fold per halving of the offset while the means do not converge (simple poles cancel in the
// mean, double ones do not). Converged: the last two levels agree to kLimitTolerance of the field's
// size nearby (absolute: a field that is zero by symmetry, e.g. c at theta = pi, is rounding there).
FieldLimit extrapolate(const double (&mean)[kLimitLevels], const double (&side)[kLimitLevels], double& value) noexcept {
  double row[kLimitLevels], largest = 0, previous_diagonal = 0;
  for (int k = 0; k < kLimitLevels; ++k) {
    row[k] = mean[k];
    largest = std::max({largest, std::abs(mean[k]), side[k]});
  }
  bool growing = true;
  for (int k = 1; k < kLimitLevels; ++k) growing = growing && side[k] >= 1.8 * side[k - 1];
  for (int j = 1; j < kLimitLevels; ++j) {
    previous_diagonal = row[j - 1];
    const double factor = double(1 << (2 * j)) - 1.0;
    for (int k = kLimitLevels - 1; k >= j; --k) row[k] += (row[k] - row[k - 1]) / factor;
  }
  value = row[kLimitLevels - 1];
  if (!growing && std::abs(value - previous_diagonal) <= kLimitTolerance * std::max(std::abs(value), largest))
    return FieldLimit::converged;
  return growing ? FieldLimit::pole : FieldLimit::failed;
}

// c replaced by the limit of the symmetric means of unchecked evaluations at theta +- kLimitStep / 2^k;
// h, lambda, h_tilde NaN (regime singular) where they have a pole at theta. False when a nearby point
// fails, or a field that cannot have a pole (c, omega'', gamma, beta, the non-resonance values) or
// only some of h's fields do not converge.
bool limit_coefficients(const ModelDefinition& d, const double* q, Index branch, NlsCoefficients& c) noexcept {
  double mean[kCheckedFieldCount][kLimitLevels], side[kCheckedFieldCount][kLimitLevels], direct[kCheckedFieldCount];
  checked_fields(c, direct);
  for (int k = 0; k < kLimitLevels; ++k) {
    const double step = kLimitStep / double(1 << k);
    NlsCoefficients plus, minus;
    if (!detail::unchecked_model_coefficients(d, q, branch, c.theta + step, plus) ||
        !detail::unchecked_model_coefficients(d, q, branch, c.theta - step, minus) ||
        plus.regime == Regime::singular || minus.regime == Regime::singular)
      return false;
    double p[kCheckedFieldCount], m[kCheckedFieldCount];
    checked_fields(plus, p);
    checked_fields(minus, m);
    for (int f = 0; f < kCheckedFieldCount; ++f) {
      mean[f][k] = 0.5 * (p[f] + m[f]);
      side[f][k] = std::max(std::abs(p[f]), std::abs(m[f]));
    }
  }
  double value[kCheckedFieldCount];
  int poles = 0;
  for (int f = 0; f < kCheckedFieldCount; ++f) {
    const FieldLimit outcome = extrapolate(mean[f], side[f], value[f]);
    if (std::isnan(value[f]) && (f >= kPoleFieldStart || std::isnan(direct[f]))) continue;  // NaN by design (on-site lambda)
    if (outcome == FieldLimit::failed || (outcome == FieldLimit::pole && f < kPoleFieldStart)) return false;
    if (outcome == FieldLimit::pole) ++poles;
  }
  NlsCoefficients limit = c;
  limit.group_velocity = value[0];
  limit.curvature = value[1];
  limit.gamma = value[2];
  limit.beta = value[3];
  limit.nonresonance1 = value[4];
  limit.nonresonance2 = value[5];
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (poles > 0) {  // h and every field built on it diverge: no NLS at this point
    limit.h = limit.lambda = limit.h_tilde = limit.h_tilde_numerator = nan;
    limit.regime = Regime::singular;
  } else {
    limit.h = value[6] / value[4];
    limit.lambda = d.mean_flow ? value[7] / value[5] : nan;
    limit.h_tilde = value[8] / (value[4] * value[5]);
    limit.h_tilde_numerator = value[8];
    const double product = limit.curvature * limit.h_tilde;
    limit.regime = product < 0 ? Regime::focusing : product > 0 ? Regime::defocusing : Regime::degenerate;
  }
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

bool implicit_derivatives(const ModelDefinition& d, const double* q, double theta, double omega,
                          BranchDerivatives& out) noexcept {
  detail::DetMAtTheta at;
  detail::half_angle_sincos(0.5 * theta, at.sin_half, at.cos_half);
  d.evaluators.evaluate_dispersion(4.0 * at.sin_half * at.sin_half, 2.0 * at.sin_half * at.cos_half, q, at.w);
  return detail::implicit_derivatives(d, q, at, omega, out);
}

bool detail::implicit_derivatives(const ModelDefinition& d, const double* q, const DetMAtTheta& at, double omega,
                                  BranchDerivatives& out) noexcept {
  // P(theta, W) = det M = sum_k w_k(theta) W^k at W = omega^2 and theta, theta +- step: P_theta,
  // P_theta_theta, P_theta_W by central differences, P_W, P_WW exactly; then W' = -P_theta / P_W,
  // W'' = -(P_theta_theta + 2 P_theta_W W' + P_WW W'^2) / P_W.
  const double W0 = omega * omega;
  // sin and cos of the half angles (theta +- step) / 2 by the addition theorem from theta / 2's;
  // those of step / 2 by their Taylor series (exact in double at this step).
  constexpr double x = 0.5 * kImplicitStep;
  constexpr double sin_x = x - x * x * x / 6.0 + x * x * x * x * x / 120.0, cos_x = 1.0 - x * x / 2.0 + x * x * x * x / 24.0;
  double P0, PW0, PWW, size;  // size: P's rounding scale at theta (the same at the nearby points)
  polynomial_derivatives(at.w, d.degree, W0, P0, PW0, PWW, size);
  double P[2], PW[2];  // at theta - step, theta + step
  for (int side = 0; side < 2; ++side) {
    const double s = side ? sin_x : -sin_x;
    const double sh = at.sin_half * cos_x + at.cos_half * s, ch = at.cos_half * cos_x - at.sin_half * s;
    double w[kMaxModelDegree + 1];
    d.evaluators.evaluate_dispersion(4.0 * sh * sh, 2.0 * sh * ch, q, w);
    polynomial_and_slope(w, d.degree, W0, P[side], PW[side]);
  }
  constexpr double h = kImplicitStep, inv_2h = 1.0 / (2.0 * h), inv_h2 = 1.0 / (h * h);
  const double Pt = (P[1] - P[0]) * inv_2h, Ptt = (P[1] - 2.0 * P0 + P[0]) * inv_h2, PtW = (PW[1] - PW[0]) * inv_2h;
  // Errors: the truncation, step^2 times P's derivatives (taken as 10 step^2 times the largest of
  // P's size, |P_theta|, |P_theta_theta|: det M is a trigonometric polynomial of low degree in
  // theta), plus the rounding of the differences (P_W's rounding taken as P's size over max(W, 1)).
  const double truncation = 10.0 * h * h * std::max({size, std::abs(Pt), std::abs(Ptt)});
  const double Pt_error = truncation + 8.0 * kEps * size * inv_2h;
  const double Ptt_error = truncation + 8.0 * kEps * size * inv_h2;
  const double PtW_error = truncation + 8.0 * kEps * size * inv_2h / std::max(W0, 1.0);
  const double inv_Pw = 1.0 / PW0, inv_2omega = 0.5 / omega;
  const double W1 = -Pt * inv_Pw, W2 = -(Ptt + 2.0 * PtW * W1 + PWW * W1 * W1) * inv_Pw;
  const double W1_error = Pt_error * std::abs(inv_Pw);
  const double W2_error =
      (Ptt_error + 2.0 * std::abs(W1) * PtW_error + (2.0 * std::abs(PtW) + 2.0 * std::abs(PWW * W1)) * W1_error) *
      std::abs(inv_Pw);
  // omega = sqrt(W): c = W' / (2 omega), omega'' = (W'' - 2 c^2) / (2 omega).
  out.group_velocity = W1 * inv_2omega;
  out.group_velocity_error = W1_error * inv_2omega;
  out.curvature = (W2 - 2.0 * out.group_velocity * out.group_velocity) * inv_2omega;
  out.curvature_error = (W2_error + 4.0 * std::abs(out.group_velocity) * out.group_velocity_error) * inv_2omega;
  return std::isfinite(out.group_velocity) && std::isfinite(out.curvature) && std::isfinite(out.curvature_error);
}

bool agrees_with_derivatives(const NlsCoefficients& c, const BranchDerivatives& d) noexcept {
  // Absolute parts scaled by omega (c and omega'' are omega per radian, per radian^2): at theta = 0
  // and pi, c = 0 by symmetry and a relative test alone would fail on rounding.
  const double tolerance = 1e-7;
  const double c_scale = std::abs(d.group_velocity) + c.omega;
  const double curvature_scale = std::abs(d.curvature) + c_scale;
  return std::abs(c.group_velocity - d.group_velocity) <= tolerance * c_scale + 10.0 * d.group_velocity_error &&
         std::abs(c.curvature - d.curvature) <= tolerance * curvature_scale + 10.0 * d.curvature_error;
}

std::string_view singular_reason(const NlsCoefficients& c) {
  if (c.evaluation == CoefficientEvaluation::refused)
    return "removable singularity of the derived expressions (0/0 at or near this wavenumber): their c or omega'' "
           "disagree with the derivatives of omega from det M, or they lose their digits, and their limit from nearby "
           "wavenumbers did not converge";
  if (c.regime == Regime::singular && c.evaluation == CoefficientEvaluation::limit)
    return "h, lambda and h_tilde have a pole at this wavenumber (their values on both sides grow without bound), e.g. "
           "where the carrier has no amplitude in the first field, whose amplitude A the NLS uses; c and omega'' are "
           "the limits of the derived expressions";
  if (c.regime == Regime::singular) return "a non-resonance condition is violated (eq:nonresonance1, eq:nonresonance2): h has a pole";
  return {};
}

namespace detail {

bool screen_passes(const ModelDefinition& d, const double* q, const NlsCoefficients& c) noexcept {
  const double theta = c.theta + kScreenStep;
  double sh, ch;
  detail::half_angle_sincos(0.5 * theta, sh, ch);
  double out[model_output_count];
  // omega there to first order (the error omega'' step^2 / 2 is below rounding).
  d.evaluators.evaluate_nls(4.0 * sh * sh, 2.0 * sh * ch, c.omega + c.group_velocity * kScreenStep, q, out);
  NlsCoefficients next;
  detail::store_linear_outputs(out, next);
  next.h = out[out_h];
  next.lambda = d.mean_flow ? out[out_lambda] : std::numeric_limits<double>::quiet_NaN();
  double here[kCheckedFieldCount], there[kCheckedFieldCount];
  checked_fields(c, here);
  checked_fields(next, there);
  for (int f = 0; f < kCheckedFieldCount; ++f)
    if (!relatively_close(here[f], there[f], kScreenTolerance)) return false;
  return true;
}

void check_or_limit(const ModelDefinition& d, const double* q, Index branch, NlsCoefficients& c) noexcept {
  BranchDerivatives derivatives;
  const bool have_derivatives = branch_derivatives(d, q, branch, c.theta, c.omega, derivatives);
  const bool derivatives_agree = !have_derivatives || agrees_with_derivatives(c, derivatives);
  if (derivatives_agree && (screen_passes(d, q, c) || c.regime == Regime::singular || smooth_at(d, q, branch, c))) return;
  if (limit_coefficients(d, q, branch, c) && (!have_derivatives || agrees_with_derivatives(c, derivatives))) return;
  refuse(c);
}

bool h_tilde_consistent(const NlsCoefficients& c) noexcept {
  if (c.regime == Regime::singular) return true;  // a violated non-resonance condition: no h to check
  // The emitted h_tilde is h - lambda beta, h and lambda each divided by its non-resonance value; the
  // emitted h_tilde_numerator is one expression. Their roundings are independent, so they disagree
  // where a 0/0 of h's expressions loses its digits (mass-in-mass-in-mass at omega^2 = k3/m3: by
  // 2e-6 at 1e-6 from the point, 3e-3 at 1e-7, 1 at 1e-8), and agree to ~1e-14 elsewhere.
  const double other = c.h_tilde_numerator / (c.nonresonance1 * c.nonresonance2);
  const double scale = std::abs(c.h) + std::abs(c.h - c.h_tilde) + std::abs(c.h_tilde);
  if (!std::isfinite(other) || !std::isfinite(scale)) return false;
  return std::abs(c.h_tilde - other) <= kConsistencyTolerance * scale;
}

void derivatives_or_check(const ModelDefinition& d, const double* q, Index branch, const DetMAtTheta& at,
                          NlsCoefficients& c) noexcept {
  BranchDerivatives det_m;
  if (h_tilde_consistent(c) && implicit_derivatives(d, q, at, c.omega, det_m) && agrees_with_derivatives(c, det_m))
    return;
  check_or_limit(d, q, branch, c);
}

}  // namespace detail
}  // namespace lrchain
