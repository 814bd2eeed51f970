#pragma once
// Boundary curves between focusing and defocusing regions as polylines, one set per cause
// (Fig. 2 legend: omega''=0, h_tilde=0, eq:nonresonance1, eq:nonresonance2), in the
// (parameter, theta) plane for parameter rho or delta0, and mapped to (delta0, omega) (Figs. 4-5).
#include <vector>

#include "lrchain/dispersion.hpp"
#include "lrchain/params.hpp"
#include "lrchain/regime/boundary_cause.hpp"
#include "lrchain/regime/zero_curve_tracing.hpp"

namespace lrchain::regime {

enum class ParameterAxis { rho, delta0 };
std::string_view to_string(ParameterAxis a);

// base with the axis parameter set to value.
Params with_parameter(Params base, ParameterAxis axis, double value);

struct BoundaryCurve {
  BoundaryCause cause = BoundaryCause::band_edge;
  Polyline points;  // x = parameter value, y = theta (or omega after to_omega_plane)
};

// Zero curves of the four smooth functions for parameter in [lo, hi], theta in [0, pi].
std::vector<BoundaryCurve> boundary_curves(const Params& base, Branch b, ParameterAxis axis,
                                           double lo, double hi, const TraceOptions& options = {});

// Maps (delta0, theta) polylines to (delta0, omega_b(theta)).
void to_omega_plane(std::vector<BoundaryCurve>& curves, const Params& base, Branch b);

}  // namespace lrchain::regime
