#pragma once
// Linear dispersion relation of the resonant chain (eq:M, eq:disp1d).
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/params.hpp"

namespace lrchain {

enum class Branch { optical, acoustic };

std::string_view to_string(Branch b);
// Parses one of branch_spellings(); throws InvalidParameter("branch", ...) naming them.
Branch parse_branch(std::string_view text);
// Every accepted spelling of a branch, for options and config keys alike:
// "optical", "opt", "+", "acoustic", "acs", "-".
const std::vector<std::string>& branch_spellings();

// omega_+(theta) (optical) or omega_-(theta) (acoustic), eq:disp1d, with K2 given.
// Evaluated without cancellation: the discriminant is written as a sum of squares and
// the acoustic root via the product of roots (omega_+^2 omega_-^2 = D kappa / rho).
double dispersion_omega(double K2, double kappa, double rho, Branch b, double theta);
double dispersion_omega(const Params& p, Branch b, double theta);

}  // namespace lrchain
