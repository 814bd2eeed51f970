// Boundary curves between focusing and defocusing regions in a (parameter, theta) plane, traced by
// pseudo-arclength continuation (Sec. 3.3): lrchain.regime.boundary_curves (regime_job.hpp).
#include <cmath>
#include <string>

#include "lrchain/dispersion.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/regime_job.hpp"
#include "lrchain/regime/model_regime.hpp"

namespace lrchain::jobs {

using namespace lrchain::regime;

namespace {

ParameterAxis parse_axis(const std::string& axis) {
  if (axis == "rho") return ParameterAxis::rho;
  if (axis == "delta0") return ParameterAxis::delta0;
  throw InvalidParameter("axis", "must be 'rho' or 'delta0', not '" + axis + "'");
}

}  // namespace

void validate(const RegimeCurvesConfig& c) {
  const double lo = c.range[0], hi = c.range[1];
  if (c.lattice.model) {
    const Model& m = *c.lattice.model;
    m.branch(c.branch);
    const ParameterLine line(m, c.axis);
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi)) throw InvalidParameter("range", "must be finite with lo < hi");
    line.check_range(lo, hi, "range");
    if (c.omega_plane) throw InvalidParameter("omega_plane", "the omega plane is the resonant chain's (Figs. 4-5)");
    return;
  }
  validate(c.lattice.params);
  parse_branch(c.branch);
  const ParameterAxis a = parse_axis(c.axis);
  if (!(std::isfinite(lo) && std::isfinite(hi) && lo > 0 && lo < hi))
    throw InvalidParameter(c.axis, "range must be finite with 0 < lo < hi");
  if (c.omega_plane && a != ParameterAxis::delta0)
    throw InvalidParameter("omega_plane", "the omega plane goes with axis='delta0' (Figs. 4-5)");
}

// The resonant chain through its specialised evaluators; a model through the generic ones.
std::vector<BoundaryCurve> run(const RegimeCurvesConfig& c) {
  validate(c);
  if (c.lattice.model) {
    const Model& m = *c.lattice.model;
    return boundary_curves(m, m.branch(c.branch), c.axis, c.range[0], c.range[1]);
  }
  const Branch b = parse_branch(c.branch);
  std::vector<BoundaryCurve> curves = boundary_curves(c.lattice.params, b, parse_axis(c.axis), c.range[0], c.range[1]);
  if (c.omega_plane) to_omega_plane(curves, c.lattice.params, b);
  return curves;
}

}  // namespace lrchain::jobs
