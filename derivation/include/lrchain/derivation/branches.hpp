#pragma once
// The branches of a derived model at given parameter values: roots of det M = 0 in omega^2,
// named acoustic/optical when one branch starts at omega = 0, else branch0, branch1, ... in
// increasing frequency; and high-precision evaluation of derived expressions on a branch.
#include <ginac/ginac.h>

#include <string>
#include <vector>

#include "lrchain/derivation/multiscale.hpp"

namespace lrchain::derivation {

struct BranchInfo {
  std::string name;
  bool real = true;             // omega^2 real and >= 0 at every sampled theta in (0, pi]
  double omega_at_zero = 0;     // omega at theta = 0
  double omega_at_pi = 0;       // omega at theta = pi
  std::string problem;          // why not real (theta and omega^2), empty when real
};

// Roots omega^2 of det M at theta (ascending; complex roots reported through `complex_found`).
std::vector<double> omega_squared_roots(const DerivedCoefficients& d, const Symbols& s, const GiNaC::exmap& values,
                                        double theta, bool& complex_found);

// Branches of the model at `values` (parameters and named intermediates as exact numbers).
std::vector<BranchInfo> find_branches(const DerivedCoefficients& d, const Symbols& s, const GiNaC::exmap& values);

// Substitutions D1, sigma, omega (branch root, polished to `digits`), c and gamma at (theta, branch).
class BranchPoint {
 public:
  BranchPoint(const DerivedCoefficients& d, const Symbols& s, const GiNaC::exmap& values, double theta,
              std::size_t branch, int digits = 40);
  GiNaC::numeric value(const GiNaC::ex& e) const;  // real part; throws if e is not a number there
  const GiNaC::exmap& substitutions() const { return subs_; }

 private:
  GiNaC::exmap subs_;
};

}  // namespace lrchain::derivation
