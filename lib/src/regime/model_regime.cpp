#include "lrchain/regime/model_regime.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "lrchain/errors.hpp"
#include "lrchain/regime/regime_map.hpp"

namespace lrchain::regime {

namespace {

// The four smooth functions from the evaluator inputs q, or NaN where the branch has no frequency.
RegimeSample sample_at(const ModelDefinition& d, const double* q, Index branch, double theta) {
  NlsCoefficients c;
  if (!coefficients_at(d, q, branch, theta, c)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan};
  }
  return regime_sample(c);
}

// Pixel of one coefficient evaluation (as the resonant chain's maps: omega'' h_tilde = 0 exactly
// is not focusing).
std::int8_t pixel_at(const ModelDefinition& d, const double* q, Index branch, double theta) {
  NlsCoefficients c;
  if (!coefficients_at(d, q, branch, theta, c)) return PixelRegime::outside;
  switch (c.regime) {
    case Regime::focusing: return PixelRegime::focusing;
    case Regime::defocusing:
    case Regime::degenerate: return PixelRegime::defocusing;
    case Regime::singular: return PixelRegime::singular;
  }
  return PixelRegime::singular;
}

void check_branch(const Model& model, Index branch) {
  if (branch < 0 || branch >= static_cast<Index>(model.definition().branch_names.size()))
    throw InvalidParameter("branch", "index out of range for model " + model.name());
}

}  // namespace

RegimeFunctions regime_functions(const Model& model, Index branch) {
  check_branch(model, branch);
  return [model, branch](double theta) {
    return sample_at(model.definition(), model.inputs().data(), branch, theta);
  };
}

std::vector<FocusingInterval> focusing_intervals(const Model& model, Index branch,
                                                 const IntervalOptions& options) {
  return regime_structure(regime_functions(model, branch), options).intervals;
}

ParameterLine::ParameterLine(const Model& base, std::string_view parameter) : base_(base) {
  const auto& parameters = definition().parameters;
  const auto it = std::find_if(parameters.begin(), parameters.end(),
                               [&](const ModelParameter& p) { return p.name == parameter; });
  if (it == parameters.end()) {
    std::string known;
    for (const auto& p : parameters) known += (known.empty() ? "" : ", ") + p.name;
    throw InvalidParameter("axis", "model " + base.name() + " has no parameter '" + std::string(parameter) +
                                       "' (its parameters: " + known + ")");
  }
  index_ = it - parameters.begin();
  if (static_cast<Index>(parameters.size()) > kMaxParameters)
    throw InvalidParameter("axis", "model " + base.name() + " has more than 64 parameters");
}

// The parameters of the base model with entry index_ replaced, then the emitted intermediates.
void ParameterLine::inputs_at(double x, std::span<double> q) const {
  const std::size_t n = definition().parameters.size();
  double p[kMaxParameters];
  std::copy_n(base_.inputs().data(), n, p);
  p[index_] = x;
  definition().evaluators.evaluate_intermediates(p, q.data());
}

void ParameterLine::check_range(double lo, double hi, const std::string& option) const {
  const ModelParameter& p = parameter();
  if (!(lo < hi)) throw InvalidParameter(option, "range needs lo < hi");
  for (double v : {lo, hi})
    if (!p.contains(v)) {
      char buffer[40];
      std::snprintf(buffer, sizeof buffer, "%.17g", v);
      throw InvalidParameter(option, std::string(buffer) + " is outside the range " + p.range_text + " of " + p.name +
                                         " (model " + definition().name + ")");
    }
}

// Sec. 3.3 for any model: per column the inputs at x_i once, then every theta_j.
ModelRegimeMap parameter_theta_map(const Model& base, Index branch, std::string_view parameter,
                                   const GridAxis& x, const GridAxis& theta) {
  check_branch(base, branch);
  const ParameterLine line(base, parameter);
  validate(x, line.parameter().name.c_str());
  validate(theta, "theta");
  line.check_range(x.lo, x.hi, line.parameter().name + "-range");
  if (!(theta.lo >= 0.0) || theta.hi > std::numbers::pi + 1e-12)
    throw InvalidParameter("theta", "range must lie in [0, pi]");
  ModelRegimeMap map{branch, line.parameter().name, x, theta,
                     std::vector<std::int8_t>(static_cast<std::size_t>(x.n) * theta.n)};
  const int nx = x.n, ny = theta.n;
  const ModelDefinition& d = base.definition();
#pragma omp parallel
  {
    std::vector<double> q(static_cast<std::size_t>(line.input_count()));
#pragma omp for schedule(static)
    for (int i = 0; i < nx; ++i) {
      line.inputs_at(x.at(i), q);
      for (int j = 0; j < ny; ++j)
        map.values[static_cast<std::size_t>(j) * nx + i] = pixel_at(d, q.data(), branch, theta.at(j));
    }
  }
  return map;
}

// The zero sets of omega'', the h_tilde numerator and both non-resonance factors in the plane.
std::vector<BoundaryCurve> boundary_curves(const Model& base, Index branch, std::string_view parameter,
                                           double lo, double hi, const TraceOptions& options) {
  check_branch(base, branch);
  const ParameterLine line(base, parameter);
  line.check_range(lo, hi, line.parameter().name + "-range");
  const double theta_lo = 1e-6;  // theta = 0 is a band edge (the acoustic mode is zero there)
  const PlaneBox box{lo, hi, theta_lo, std::numbers::pi};
  std::vector<double> q(static_cast<std::size_t>(line.input_count()));
  std::vector<BoundaryCurve> out;
  for (BoundaryCause cause : kSmoothCauses) {
    const auto F = [&](double x, double theta) {
      line.inputs_at(x, q);
      return sample_at(base.definition(), q.data(), branch, theta)[cause];
    };
    for (auto& polyline : trace_zero_set(F, box, options)) out.push_back({cause, std::move(polyline)});
  }
  return out;
}

std::vector<RegimeEvent> regime_events(const Model& base, Index branch, std::string_view parameter,
                                       const GridAxis& scan, const EventOptions& options) {
  check_branch(base, branch);
  const ParameterLine line(base, parameter);
  validate(scan, line.parameter().name.c_str());
  line.check_range(scan.lo, scan.hi, line.parameter().name + "-range");
  const RegimeFamily family = [&line, branch](double value) {
    std::vector<double> q(static_cast<std::size_t>(line.input_count()));
    line.inputs_at(value, q);
    const ModelDefinition* d = &line.definition();
    return RegimeFunctions([d, q = std::move(q), branch](double theta) { return sample_at(*d, q.data(), branch, theta); });
  };
  return regime_events(family, scan, options);
}

}  // namespace lrchain::regime
