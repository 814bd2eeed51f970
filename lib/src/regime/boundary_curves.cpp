#include "lrchain/regime/boundary_curves.hpp"

#include <numbers>

#include "lrchain/coefficients.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/regime/regime_functions.hpp"

namespace lrchain::regime {

std::string_view to_string(ParameterAxis a) { return a == ParameterAxis::rho ? "rho" : "delta0"; }

Params with_parameter(Params base, ParameterAxis axis, double value) {
  (axis == ParameterAxis::rho ? base.rho : base.delta0) = value;
  return base;
}

// Zero sets of omega'', the h_tilde numerator, eq:nonresonance1 and eq:nonresonance2 in the
// (parameter, theta) plane (Fig. 2 boundary lines), each traced by continuation.
std::vector<BoundaryCurve> boundary_curves(const Params& base, Branch b, ParameterAxis axis,
                                           double lo, double hi, const TraceOptions& options) {
  validate(base);
  if (!(lo > 0.0 && hi > lo))
    throw InvalidParameter(std::string(to_string(axis)), "range must satisfy 0 < lo < hi");
  const double theta_lo = 1e-6;  // theta = 0 is a band edge (the acoustic mode is zero there)
  const PlaneBox box{lo, hi, theta_lo, std::numbers::pi};
  std::vector<BoundaryCurve> out;
  for (BoundaryCause cause : kSmoothCauses) {
    const auto F = [&](double x, double theta) {
      const Params p = with_parameter(base, axis, x);
      return regime_sample(coefficients_unchecked(p, taylor_coefficients(p), b, theta))[cause];
    };
    for (auto& line : trace_zero_set(F, box, options)) out.push_back({cause, std::move(line)});
  }
  return out;
}

void to_omega_plane(std::vector<BoundaryCurve>& curves, const Params& base, Branch b) {
  for (auto& c : curves)
    for (auto& pt : c.points) {
      const Params p = with_parameter(base, ParameterAxis::delta0, pt.x);
      pt.y = dispersion_omega(p, b, pt.y);
    }
}

}  // namespace lrchain::regime
