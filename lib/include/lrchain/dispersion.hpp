#pragma once
// Linear dispersion relation of the resonant chain (eq:M, eq:disp1d).
#include <string_view>

#include "lrchain/params.hpp"

namespace lrchain {

enum class Branch { optical, acoustic };

std::string_view to_string(Branch b);
// Parses "optical"/"acoustic" (also "+"/"-"); throws InvalidParameter("branch", ...).
Branch parse_branch(std::string_view text);

// omega_+(theta) (optical) or omega_-(theta) (acoustic), eq:disp1d, with K2 given.
// Evaluated without cancellation: the discriminant is written as a sum of squares and
// the acoustic root via the product of roots (omega_+^2 omega_-^2 = D kappa / rho).
double dispersion_omega(double K2, double kappa, double rho, Branch b, double theta);
double dispersion_omega(const Params& p, Branch b, double theta);

}  // namespace lrchain
