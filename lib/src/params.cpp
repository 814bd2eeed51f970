#include "lrchain/params.hpp"

#include <cmath>
#include <cstdio>

#include "lrchain/errors.hpp"

namespace lrchain {

namespace {

// A bound or a value as messages show it: %g ("10000", "1e+308", "0.444444").
std::string shown(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

}  // namespace

bool PhysicalRange::contains(double value) const {
  if (!std::isfinite(value)) return false;
  if (min_open ? !(value > min) : !(value >= min)) return false;
  return max_open ? value < max : value <= max;
}

std::string PhysicalRange::interval() const {
  return std::string(min_open ? "(" : "[") + shown(min) + ", " + shown(max) + (max_open ? ")" : "]");
}

const std::vector<PhysicalRange>& model_parameter_ranges() {
  static const std::vector<PhysicalRange> ranges = {alpha_range, delta0_range, kappa_range, rho_range};
  return ranges;
}

void check_in_range(double value, const PhysicalRange& range, const std::string& name) {
  if (range.contains(value)) return;
  throw InvalidParameter(name.empty() ? std::string(range.name) : name,
                         "must be a finite number in " + range.interval() + " (" + range.meaning + "); got " +
                             shown(value));
}

void validate(const Params& p) {
  check_in_range(p.alpha, alpha_range);
  check_in_range(p.delta0, delta0_range);
  check_in_range(p.kappa, kappa_range);
  check_in_range(p.rho, rho_range);
}

void check_drive_amplitude(double amplitude, double delta0) {
  if (std::isfinite(amplitude) && amplitude > 0 && amplitude <= delta0) return;
  throw InvalidParameter("amplitude", "must be a finite number in (0, delta0] = (0, " + shown(delta0) +
                                          "] (the driver's stroke may not exceed the precompression overlap); got " +
                                          shown(amplitude));
}

TaylorCoefficients taylor_coefficients(const Params& p) {
  const double a = p.alpha;
  const double d3 = std::pow(p.delta0, a - 3.0);  // one pow: delta0^(alpha-3)
  const double d2 = d3 * p.delta0;
  const double d1 = d2 * p.delta0;
  return {a * d1, -0.5 * a * (a - 1.0) * d2, a * (a - 1.0) * (a - 2.0) * d3 / 6.0};
}

double hertz_force(double r, double alpha, double delta0) {
  const double s = delta0 - r;
  const double contact = s > 0.0 ? std::pow(s, alpha) : 0.0;
  return std::pow(delta0, alpha) - contact;
}

}  // namespace lrchain
