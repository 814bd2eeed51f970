// Shared parts of the regime jobs (regime_lattice.hpp).
#include "regime_lattice.hpp"

#include <cmath>
#include <numbers>

#include "lrchain/errors.hpp"
#include "lrchain/regime/model_regime.hpp"

namespace lrchain::jobs {

RegimeLattice resonant_chain_lattice(const Model& m) {
  return {Params{m.parameter("alpha"), m.parameter("delta0"), m.parameter("kappa"), m.parameter("rho")}, nullptr};
}

namespace {

// rho for the resonant chain (null: through Params), else the model's first parameter.
std::string default_axis_of(const Model* m) {
  if (m == nullptr || m->name() == "resonant_chain") return "rho";
  return m->definition().parameters.at(0).name;
}

}  // namespace

std::string default_axis(const RegimeLattice& lattice) { return default_axis_of(lattice.model.get()); }

}  // namespace lrchain::jobs

namespace lrchain::jobs::regime_detail {

using nlohmann::json;
using namespace lrchain::regime;

Index model_branch(const Model& m, const std::string& name) {
  if (!name.empty() || m.definition().branch_names.size() == 1) return m.branch_or_only(name);
  return m.branch("optical");
}

void refuse_branch_without_real_frequency(const Model& model, Index branch, int samples) {
  const RegimeFunctions f = regime_functions(model, branch);
  for (int k = 1; k <= samples; ++k)
    if (!std::isnan(f(std::numbers::pi * double(k) / double(samples)).curvature)) return;
  const std::string& name = model.definition().branch_names[static_cast<std::size_t>(branch)];
  throw InvalidParameter("branch", "branch '" + name + "' of model '" + model.name() +
                                       "' has no real positive frequency on (0, pi] at these parameters (omega^2 <= 0: "
                                       "the lattice is unstable), so it has no focusing or defocusing regimes");
}

void check_increasing(const Range& r, const std::string& key) {
  if (!(r[0] < r[1])) throw InvalidParameter(key, "range needs lo < hi");
}

namespace {

// Default axis range: the resonant chain's rho as in Fig. 2, else the parameter's declared range
// when it is bounded (open ends moved inwards by 1e-3 of its width).
Range default_axis_range(const Model& m, const ParameterLine& line, Index branch) {
  if (m.name() == "resonant_chain" && line.parameter().name == "rho")
    return default_rho_range(m.definition().branch_names[static_cast<std::size_t>(branch)] == "optical"
                                 ? Branch::optical
                                 : Branch::acoustic);
  const ModelParameter& p = line.parameter();
  if (!(p.has_lower && p.has_upper))
    throw InvalidParameter("axis_range", "is required for " + p.name + " (its range " + p.range_text +
                                             " is unbounded), e.g. --axis-range 0.5 2");
  const double width = p.upper - p.lower;
  return {p.lower_closed ? p.lower : p.lower + 1e-3 * width, p.upper_closed ? p.upper : p.upper - 1e-3 * width};
}

}  // namespace

ModelAxisPlan plan_model_axis(const Model& m, const std::string& axis, const std::string& branch,
                              const std::optional<Range>& axis_range) {
  ModelAxisPlan plan;
  plan.axis = !axis.empty() ? axis : default_axis_of(&m);
  const ParameterLine line(m, plan.axis);
  if (branch == "both" || branch == "all") {
    for (auto b = static_cast<Index>(m.definition().branch_names.size()); b-- > 0;) plan.branches.push_back(b);
  } else {
    plan.branches.push_back(m.branch(branch));
  }
  for (Index b : plan.branches) {
    if (axis_range) check_increasing(*axis_range, "axis_range");
    plan.ranges.push_back(axis_range ? *axis_range : default_axis_range(m, line, b));
    line.check_range(plan.ranges.back()[0], plan.ranges.back()[1], "axis_range");
  }
  return plan;
}

json interval_json(const FocusingInterval& i) {
  return {{"lo", i.lo},
          {"hi", i.hi},
          {"lo_cause", std::string(to_string(i.lo_cause))},
          {"hi_cause", std::string(to_string(i.hi_cause))}};
}

json event_json(const RegimeEvent& e) {
  json causes = json::array();
  for (auto c : e.causes) causes.push_back(std::string(to_string(c)));
  json j = {{"value", e.value},
            {"kind", std::string(to_string(e.kind))},
            {"causes", causes},
            {"focusing_intervals_before", e.intervals_before},
            {"focusing_intervals_after", e.intervals_after}};
  j["theta"] = std::isfinite(e.theta) ? json(e.theta) : json(nullptr);
  return j;
}

}  // namespace lrchain::jobs::regime_detail
