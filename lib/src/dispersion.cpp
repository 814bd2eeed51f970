#include "lrchain/dispersion.hpp"

#include <cmath>

#include "lrchain/errors.hpp"
#include "lrchain/half_angle.hpp"

namespace lrchain {

std::string_view to_string(Branch b) { return b == Branch::optical ? "optical" : "acoustic"; }

const std::vector<std::string>& branch_spellings() {
  static const std::vector<std::string> names = {"optical", "opt", "+", "acoustic", "acs", "-"};
  return names;
}

Branch parse_branch(std::string_view text) {
  if (text.empty()) throw InvalidParameter("branch", "is required: 'optical' (or 'opt', '+') or 'acoustic' (or 'acs', '-')");
  if (text == "optical" || text == "+" || text == "opt") return Branch::optical;
  if (text == "acoustic" || text == "-" || text == "acs") return Branch::acoustic;
  throw InvalidParameter("branch", "must be 'optical' (or 'opt', '+') or 'acoustic' (or 'acs', '-'), got '" +
                                       std::string(text) + "'");
}

// eq:disp1d: omega^2 = (S +- sqrt(S^2 - 4 D kappa/rho))/2, S = D + kappa + kappa/rho,
// with S^2 - 4 D kappa/rho = (D + kappa - kappa/rho)^2 + 4 kappa^2/rho.
double dispersion_omega(double K2, double kappa, double rho, Branch b, double theta) {
  double sh, ch;
  detail::half_angle_sincos(0.5 * theta, sh, ch);
  const double D = 4.0 * K2 * sh * sh;
  const double kr = kappa / rho;
  const double S = D + kappa + kr;
  const double m = D + kappa - kr;
  const double root = std::sqrt(m * m + 4.0 * kappa * kr);
  const double upper = 0.5 * (S + root);
  if (b == Branch::optical) return std::sqrt(upper);
  return std::sqrt(D * kr / upper);
}

double dispersion_omega(const Params& p, Branch b, double theta) {
  return dispersion_omega(taylor_coefficients(p).K2, p.kappa, p.rho, b, theta);
}

}  // namespace lrchain
