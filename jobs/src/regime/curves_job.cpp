// Boundary curves between focusing and defocusing regions in a (parameter, theta) plane, traced by
// pseudo-arclength continuation (Sec. 3.3): lrchain.regime.boundary_curves (regime_job.hpp).
#include <cmath>
#include <string>

#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/regime/model_regime.hpp"
#include "regime_lattice.hpp"

namespace lrchain::jobs {

using namespace lrchain::regime;
using namespace regime_detail;

namespace {

ParameterAxis parse_axis(const std::string& axis) {
  if (axis == "rho") return ParameterAxis::rho;
  if (axis == "delta0") return ParameterAxis::delta0;
  throw InvalidParameter("axis", "must be 'rho' or 'delta0', not '" + axis + "'");
}

}  // namespace

Range default_axis_range(const RegimeLattice& lattice, const std::string& axis, const std::string& branch) {
  if (lattice.model) return plan_model_axis(*lattice.model, axis, branch, std::nullopt).ranges.at(0);
  if (parse_axis(axis.empty() ? "rho" : axis) == ParameterAxis::delta0) return default_delta0_range;
  return default_rho_range(parse_branch(branch));
}

void validate(const RegimeCurvesConfig& c) {
  if (c.lattice.model) {
    if (c.omega_plane) throw InvalidParameter("omega_plane", "the omega plane is the resonant chain's (Figs. 4-5)");
    plan_model_axis(*c.lattice.model, c.axis, c.branch, c.range);
    return;
  }
  validate(c.lattice.params);
  parse_branch(c.branch);
  const ParameterAxis a = parse_axis(c.axis.empty() ? "rho" : c.axis);
  if (c.range) {
    const double lo = (*c.range)[0], hi = (*c.range)[1];
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo > 0 && lo < hi))
      throw InvalidParameter("range", "must be finite with 0 < lo < hi");
  }
  if (c.omega_plane && a != ParameterAxis::delta0)
    throw InvalidParameter("omega_plane", "the omega plane goes with axis='delta0' (Figs. 4-5)");
}

// The resonant chain through its specialised evaluators; a model through the generic ones.
std::vector<BoundaryCurve> run(const RegimeCurvesConfig& c) {
  validate(c);
  if (c.lattice.model) {
    const Model& m = *c.lattice.model;
    const ModelAxisPlan plan = plan_model_axis(m, c.axis, c.branch, c.range);
    return boundary_curves(m, plan.branches.at(0), plan.axis, plan.ranges[0][0], plan.ranges[0][1]);
  }
  const Branch b = parse_branch(c.branch);
  const std::string axis = c.axis.empty() ? "rho" : c.axis;
  const Range r = c.range.value_or(default_axis_range(c.lattice, axis, c.branch));
  std::vector<BoundaryCurve> curves = boundary_curves(c.lattice.params, b, parse_axis(axis), r[0], r[1]);
  if (c.omega_plane) to_omega_plane(curves, c.lattice.params, b);
  return curves;
}

}  // namespace lrchain::jobs
