#include "lrchain/model.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <numbers>

#include "lrchain/errors.hpp"
#include "lrchain/half_angle.hpp"
#include "coefficient_check.hpp"

namespace lrchain {

bool ModelParameter::contains(double v) const {
  if (!std::isfinite(v)) return false;
  if (has_lower && (lower_closed ? v < lower : v <= lower)) return false;
  if (has_upper && (upper_closed ? v > upper : v >= upper)) return false;
  return true;
}

std::string model_hash_text(std::uint64_t hash) {
  char buffer[19];
  std::snprintf(buffer, sizeof buffer, "0x%016llx", static_cast<unsigned long long>(hash));
  return buffer;
}

std::uint64_t fnv1a_64(std::string_view bytes, std::uint64_t hash) {
  for (unsigned char c : bytes) hash = (hash ^ c) * 1099511628211ull;
  return hash;
}

const ModelDefinition* find_shipped_model(std::string_view name) {
  for (const auto& m : shipped_models())
    if (m.name == name) return &m;
  return nullptr;
}

Model shipped_model(std::string_view name, const std::vector<std::pair<std::string, double>>& values) {
  const ModelDefinition* d = find_shipped_model(name);
  if (!d) {
    std::string known;
    for (const auto& m : shipped_models()) known += (known.empty() ? "" : ", ") + m.name;
    throw InputError("no shipped model '" + std::string(name) + "' (shipped: " + known + ")");
  }
  // Shipped definitions live for the whole program: share them without owning.
  return Model(std::shared_ptr<const ModelDefinition>(std::shared_ptr<const ModelDefinition>(), d), values);
}

bool ModelDefinition::is_resonant_chain() const {
  const ModelDefinition* shipped = find_shipped_model("resonant_chain");
  return shipped && (this == shipped || (!file_sha256.empty() && file_sha256 == shipped->file_sha256));
}

Model resonant_chain_model(const Params& p) {
  return shipped_model("resonant_chain", {{"alpha", p.alpha}, {"delta0", p.delta0}, {"kappa", p.kappa}, {"rho", p.rho}});
}

// Defaults, overrides checked against their ranges, then the evaluator's intermediates.
Model::Model(std::shared_ptr<const ModelDefinition> definition, const std::vector<std::pair<std::string, double>>& values)
    : definition_(std::move(definition)) {
  const auto& parameters = definition_->parameters;
  std::vector<double> p;
  for (const auto& parameter : parameters) p.push_back(parameter.default_value);
  for (const auto& [name, value] : values) {
    const std::string_view wanted = name;  // a lambda may not capture a structured binding (clang 14)
    auto it = std::find_if(parameters.begin(), parameters.end(), [&](const auto& q) { return q.name == wanted; });
    if (it == parameters.end()) {
      std::string known;
      for (const auto& q : parameters) known += (known.empty() ? "" : ", ") + q.name;
      throw InvalidParameter(name, "model " + definition_->name + " has no such parameter (its parameters: " + known + ")");
    }
    if (!it->contains(value)) {
      char buffer[40];
      std::snprintf(buffer, sizeof buffer, "%.17g", value);
      throw InvalidParameter(name, std::string(buffer) + " is outside its range " + it->range_text + " (model " +
                                       definition_->name + ")");
    }
    p[std::size_t(it - parameters.begin())] = value;
  }
  q_.assign(parameters.size() + definition_->intermediates.size(), 0.0);
  definition_->evaluators.evaluate_intermediates(p.data(), q_.data());
  for (std::size_t i = parameters.size(); i < q_.size(); ++i)
    if (!std::isfinite(q_[i]))
      throw InvalidParameter(definition_->intermediates[i - parameters.size()],
                             "is not finite at these parameter values (model " + definition_->name + ")");
  if (definition_->is_resonant_chain()) {  // the specialised evaluators' inputs, once
    resonant_chain_params_ = Params{parameter("alpha"), parameter("delta0"), parameter("kappa"), parameter("rho")};
    resonant_chain_K_ = taylor_coefficients(*resonant_chain_params_);
    optical_branch_ = branch("optical");
  }
}

double Model::parameter(std::string_view name) const {
  const auto& parameters = definition_->parameters;
  for (std::size_t i = 0; i < parameters.size(); ++i)
    if (parameters[i].name == name) return q_[i];
  throw InvalidParameter(std::string(name), "model " + definition_->name + " has no such parameter");
}

namespace {

// 'a', 'b', 'c': a model's branch names as messages list them.
std::string quoted_branch_names(const std::vector<std::string>& names) {
  std::string known;
  for (const auto& n : names) known += (known.empty() ? "'" : ", '") + n + "'";
  return known;
}

}  // namespace

Index Model::branch(std::string_view name) const {
  const auto& names = definition_->branch_names;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == name) return static_cast<Index>(i);
  throw InvalidParameter("branch", "model " + definition_->name + " has the branches " + quoted_branch_names(names) +
                                       ", not '" + std::string(name) + "'");
}

Index Model::branch_or_only(std::string_view name) const {
  const auto& names = definition_->branch_names;
  if (!name.empty()) return branch(name);
  if (names.size() == 1) return 0;
  throw InvalidParameter("branch", "is required: model " + definition_->name + " has the branches " +
                                       quoted_branch_names(names));
}

// Linear and quadratic in closed form (the quadratic without cancellation), higher degrees by
// Durand-Kerner iteration on fixed-size arrays.
bool omega_squared_roots(const double* c, Index degree, double* roots) {
  if (degree == 1) {
    roots[0] = -c[0] / c[1];
    return std::isfinite(roots[0]);
  }
  if (degree == 2) {
    const double a = c[2], b = c[1], c0 = c[0];
    const double disc = b * b - 4.0 * a * c0;
    if (disc < -1e-14 * (b * b + std::abs(4.0 * a * c0))) return false;
    const double q = -0.5 * (b + std::copysign(std::sqrt(std::max(disc, 0.0)), b));
    const double r1 = q / a, r2 = q != 0.0 ? c0 / q : r1;
    roots[0] = std::min(r1, r2);
    roots[1] = std::max(r1, r2);
    return std::isfinite(roots[0]) && std::isfinite(roots[1]);
  }
  if (degree < 1 || degree > kMaxModelDegree) return false;
  std::complex<double> z[kMaxModelDegree];
  const std::complex<double> seed(0.4, 0.9);
  double radius = 0;
  for (int k = 0; k < degree; ++k) radius = std::max(radius, std::abs(c[k] / c[degree]));
  z[0] = seed * (1.0 + radius);
  for (int k = 1; k < degree; ++k) z[k] = z[k - 1] * seed;
  for (int iteration = 0; iteration < 500; ++iteration) {
    double change = 0;
    for (int i = 0; i < degree; ++i) {
      std::complex<double> p = c[degree];
      for (int k = degree - 1; k >= 0; --k) p = p * z[i] + c[k];
      std::complex<double> d = c[degree];
      for (int j = 0; j < degree; ++j)
        if (j != i) d *= z[i] - z[j];
      const std::complex<double> step = p / d;
      z[i] -= step;
      change = std::max(change, std::abs(step) / std::max(1.0, std::abs(z[i])));
    }
    if (change < 1e-15) break;
  }
  for (int i = 0; i < degree; ++i) {
    if (std::abs(z[i].imag()) > 1e-9 * std::max(1.0, std::abs(z[i]))) return false;
    roots[i] = z[i].real();
  }
  std::sort(roots, roots + degree);
  return true;
}

namespace {

// Roots of det M in omega^2, the branch's omega, the emitted NLS evaluator, the singular test
// (inlined into both entry points: this is the hot path of every map and scan).
[[gnu::always_inline]] inline bool evaluate_unchecked(const ModelDefinition& d, const double* q, Index branch,
                                                      double theta, NlsCoefficients& c, detail::DetMAtTheta& at) noexcept {
  double& sh = at.sin_half;
  double& ch = at.cos_half;
  detail::half_angle_sincos(0.5 * theta, sh, ch);
  const double D1 = 4.0 * sh * sh;  // no cancellation near theta = 0
  const double sigma = 2.0 * sh * ch;
  double* w = at.w;
  double roots[kMaxModelDegree];
  d.evaluators.evaluate_dispersion(D1, sigma, q, w);
  if (!omega_squared_roots(w, d.degree, roots)) return false;
  const double w2 = roots[branch];
  if (!(w2 > 0.0)) return false;
  const double omega = std::sqrt(w2);
  double out[model_output_count];
  d.evaluators.evaluate_nls(D1, sigma, omega, q, out);
  c.theta = theta;
  c.omega = omega;
  detail::store_linear_outputs(out, c);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  if (std::abs(c.nonresonance1) <= kNonresonanceTolerance * out[out_nonresonance1_scale] ||
      std::abs(c.nonresonance2) <= kNonresonanceTolerance * out[out_nonresonance2_scale]) {
    c.h = c.lambda = c.h_tilde = nan;
    c.regime = Regime::singular;
    return true;
  }
  c.h = out[out_h];
  c.lambda = d.mean_flow ? out[out_lambda] : nan;
  c.h_tilde = out[out_h_tilde];
  const double product = c.curvature * c.h_tilde;
  c.regime = product < 0 ? Regime::focusing : product > 0 ? Regime::defocusing : Regime::degenerate;
  return true;
}

// The unchecked evaluation, then its check (coefficient_check.cpp): full (c, omega'' against omega's
// derivatives from det M, digits lost to a 0/0) for one wavenumber's numbers, or the hot path's
// (c, omega'' against det M's implicit derivatives) with the full check where they disagree.
template <bool full>
[[gnu::always_inline]] inline bool evaluate_coefficients(const ModelDefinition& d, const double* q, Index branch,
                                                         double theta, NlsCoefficients& c) noexcept {
  detail::DetMAtTheta at;
  if (!evaluate_unchecked(d, q, branch, theta, c, at)) return false;
  if constexpr (full) detail::check_or_limit(d, q, branch, c);
  else detail::derivatives_or_check(d, q, branch, at, c);
  return true;
}

// The coefficients at `parameters` (one value per parameter), intermediates recomputed.
bool coefficients_with(const ModelDefinition& d, const std::vector<double>& parameters, Index branch, double theta) {
  std::vector<double> q(d.parameters.size() + d.intermediates.size(), 0.0);
  d.evaluators.evaluate_intermediates(parameters.data(), q.data());
  NlsCoefficients c;
  detail::DetMAtTheta at;
  return evaluate_unchecked(d, q.data(), branch, theta, c, at);
}

// Where the coefficients at (branch, theta) fail although they exist there at the model's defaults:
// the one parameter whose own default brings them back (e.g. a = 1e-300 underflows omega^2 to 0),
// as an InvalidParameter of that name; nothing when theta itself is the cause.
void blame_parameter(const Model& model, Index branch, double theta) {
  const ModelDefinition& d = model.definition();
  const std::size_t n = d.parameters.size();
  std::vector<double> defaults;
  for (const auto& p : d.parameters) defaults.push_back(p.default_value);
  if (!coefficients_with(d, defaults, branch, theta)) return;  // no frequency here even at the defaults
  const std::vector<double> values(model.inputs().begin(), model.inputs().begin() + std::ptrdiff_t(n));
  const auto text = [](double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    return std::string(buffer);
  };
  std::string changed;
  for (std::size_t i = 0; i < n; ++i) {
    if (values[i] == defaults[i]) continue;
    changed += (changed.empty() ? "" : ", ") + d.parameters[i].name + " = " + text(values[i]);
    std::vector<double> trial = values;
    trial[i] = defaults[i];
    if (coefficients_with(d, trial, branch, theta))
      throw InvalidParameter(d.parameters[i].name,
                             text(values[i]) + " leaves branch " + d.branch_names[std::size_t(branch)] + " of model " + d.name +
                                 " without a positive frequency at theta = " + text(theta) +
                                 " (it vanishes or underflows in double precision); at its default " + text(defaults[i]) +
                                 " the coefficients exist there");
  }
  throw InvalidParameter(changed.substr(0, changed.find(" =")),
                         "the coefficients of branch " + d.branch_names[std::size_t(branch)] + " of model " + d.name +
                             " cannot be evaluated at theta = " + text(theta) + " with " + changed +
                             " (no positive frequency in double precision); at the model's defaults they can");
}

}  // namespace

bool detail::unchecked_model_coefficients(const ModelDefinition& d, const double* q, Index branch, double theta,
                                          NlsCoefficients& c) noexcept {
  detail::DetMAtTheta at;
  return evaluate_unchecked(d, q, branch, theta, c, at);
}

bool coefficients_at(const ModelDefinition& d, const double* q, Index branch, double theta,
                     NlsCoefficients& c) noexcept {
  return evaluate_coefficients<false>(d, q, branch, theta, c);
}

namespace {

// The checks of theta and branch both entry points share.
void check_wavenumber_and_branch(const ModelDefinition& d, Index branch, double theta) {
  if (!(std::isfinite(theta) && theta > -std::numbers::pi && theta <= std::numbers::pi))
    throw InvalidParameter("theta", "must be a wavenumber in (-pi, pi]");
  if (branch < 0 || branch >= static_cast<Index>(d.branch_names.size()))
    throw InvalidParameter("branch", "index out of range for model " + d.name);
}

// The model's own evaluators at a checked theta and branch; InvalidParameter("theta") naming why
// the branch has no frequency there.
NlsCoefficients checked_evaluator_coefficients(const Model& model, Index branch, double theta) {
  const ModelDefinition& d = model.definition();
  NlsCoefficients c;
  if (evaluate_coefficients<true>(d, model.inputs().data(), branch, theta, c)) [[likely]] return c;
  double w[kMaxModelDegree + 1], roots[kMaxModelDegree];
  double sh, ch;
  detail::half_angle_sincos(0.5 * theta, sh, ch);
  d.evaluators.evaluate_dispersion(4.0 * sh * sh, 2.0 * sh * ch, model.inputs().data(), w);
  blame_parameter(model, branch, theta);
  if (!omega_squared_roots(w, d.degree, roots))
    throw InvalidParameter("theta", "model " + d.name + " has no real frequency at this wavenumber");
  throw InvalidParameter("theta", "branch " + d.branch_names[static_cast<std::size_t>(branch)] + " of model " + d.name +
                                      " has no positive frequency here (theta = 0 on an acoustic branch is the "
                                      "zero-frequency mode)");
}

}  // namespace

NlsCoefficients coefficients(const Model& model, Index branch, double theta) {
  check_wavenumber_and_branch(model.definition(), branch, theta);
  if (const std::optional<Params>& p = model.resonant_chain_params()) {  // the paper's chain: its fast path
    const Branch b = model.resonant_chain_branch(branch);
    if (!(b == Branch::acoustic && theta == 0.0)) [[likely]]
      return coefficients_unchecked(*p, model.resonant_chain_taylor_coefficients(), b, theta);
  }
  return checked_evaluator_coefficients(model, branch, theta);  // (the chain's zero-frequency mode: its message)
}

NlsCoefficients coefficients_from_evaluators(const Model& model, Index branch, double theta) {
  check_wavenumber_and_branch(model.definition(), branch, theta);
  return checked_evaluator_coefficients(model, branch, theta);
}

}  // namespace lrchain
