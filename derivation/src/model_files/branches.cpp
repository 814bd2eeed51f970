#include "lrchain/derivation/branches.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "lrchain/derivation/evaluate.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

// Coefficients (ascending powers of w2 = omega^2) of det M at the point, as real numerics.
std::vector<numeric> dispersion_polynomial(const DerivedCoefficients& d, const Symbols& s, const exmap& point) {
  const realsymbol w2("w2");
  const ex F = expand(numer(normal(d.dispersion)).subs(point, subs_options::no_pattern).subs(s.omega == sqrt(w2)));
  std::vector<numeric> c;
  for (int k = 0; k <= F.degree(w2); ++k) {
    const ex v = evalf(F.coeff(w2, k));
    if (!is_a<numeric>(v)) throw std::runtime_error("det M is not a polynomial in omega^2 with numeric coefficients");
    c.push_back(ex_to<numeric>(v).real());
  }
  while (c.size() > 1 && c.back().is_zero()) c.pop_back();
  if (c.size() < 2) throw std::runtime_error("det M does not depend on omega");
  return c;
}

exmap trig_point(const Symbols& s, const exmap& values, const numeric& theta) {
  exmap p = values;
  const numeric half = ex_to<numeric>(evalf(sin(theta / 2)));
  p[s.D1] = 4 * half * half;
  p[s.sigma] = ex_to<numeric>(evalf(sin(theta)));
  return p;
}

// Roots of the polynomial (companion-matrix eigenvalues), ascending by real part.
std::vector<std::complex<double>> roots(const std::vector<numeric>& c) {
  const int n = int(c.size()) - 1;
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  const double lead = c[n].to_double();
  for (int i = 0; i < n; ++i) {
    companion(0, i) = -c[n - 1 - i].to_double() / lead;
    if (i + 1 < n) companion(i + 1, i) = 1;
  }
  Eigen::EigenSolver<Eigen::MatrixXd> solver(companion, false);
  std::vector<std::complex<double>> r(solver.eigenvalues().data(), solver.eigenvalues().data() + n);
  std::sort(r.begin(), r.end(), [](auto a, auto b) { return a.real() < b.real(); });
  return r;
}

}  // namespace

std::vector<double> omega_squared_roots(const DerivedCoefficients& d, const Symbols& s, const exmap& values,
                                        double theta, bool& complex_found) {
  Digits = 30;
  const auto c = dispersion_polynomial(d, s, trig_point(s, values, exact(theta)));
  complex_found = false;
  std::vector<double> out;
  double scale = 0;
  for (const auto& r : roots(c)) scale = std::max(scale, std::abs(r));
  for (const auto& r : roots(c)) {
    if (std::abs(r.imag()) > 1e-9 * std::max(scale, 1e-300)) complex_found = true;
    out.push_back(r.real());
  }
  return out;
}

std::vector<BranchInfo> find_branches(const DerivedCoefficients& d, const Symbols& s, const exmap& values) {
  bool complex_found = false;
  const auto at_zero = omega_squared_roots(d, s, values, 0.0, complex_found);
  const double scale = std::max(1e-300, std::abs(at_zero.back()));
  const bool acoustic = !complex_found && std::abs(at_zero.front()) <= 1e-10 * scale;
  std::vector<BranchInfo> b(at_zero.size());
  for (std::size_t i = 0; i < b.size(); ++i) {
    if (acoustic) b[i].name = i == 0 ? "acoustic" : (b.size() == 2 ? "optical" : "optical" + std::to_string(i));
    else b[i].name = "branch" + std::to_string(i);
    b[i].omega_at_zero = (acoustic && i == 0) ? 0.0 : std::sqrt(std::max(0.0, at_zero[i]));
  }
  const int samples = 64;
  for (int k = 1; k <= samples; ++k) {
    const double theta = M_PI * k / samples;
    const auto r = omega_squared_roots(d, s, values, theta, complex_found);
    for (std::size_t i = 0; i < b.size(); ++i) {
      if (i < r.size()) b[i].omega_at_pi = std::sqrt(std::max(0.0, r[i]));
      if (b[i].real && (complex_found || i >= r.size() || r[i] < 0)) {
        b[i].real = false;
        std::ostringstream os;
        os << "omega^2 " << (complex_found ? "complex" : "= " + std::to_string(r[i])) << " at theta = " << theta;
        b[i].problem = os.str();
      }
    }
  }
  return b;
}

BranchPoint::BranchPoint(const DerivedCoefficients& d, const Symbols& s, const exmap& values, double theta,
                         std::size_t branch, int digits) {
  Digits = digits;
  subs_ = trig_point(s, values, exact(theta));
  const auto c = dispersion_polynomial(d, s, subs_);
  const auto r = roots(c);
  if (branch >= r.size()) throw std::runtime_error("no such branch");
  // Newton polish of the double root at `digits` digits.
  numeric w2 = exact(r[branch].real());
  for (int iteration = 0; iteration < 12; ++iteration) {
    numeric p = 0, dp = 0;
    for (std::size_t k = c.size(); k-- > 0;) {
      dp = dp * w2 + p;
      p = p * w2 + c[k];
    }
    if (dp.is_zero()) break;
    w2 = w2 - p / dp;
  }
  if (w2.is_negative()) throw std::runtime_error("negative omega^2 on this branch");
  subs_[s.omega] = ex_to<numeric>(evalf(sqrt(w2)));
  subs_[s.c] = value(d.group_velocity);
  subs_[s.gamma] = value(d.gamma);
}

numeric BranchPoint::value(const ex& e) const {
  const ex v = evalf(e.subs(subs_, subs_options::no_pattern));
  if (!is_a<numeric>(v)) throw std::runtime_error("expression did not evaluate to a number");
  return ex_to<numeric>(v).real();
}

}  // namespace lrchain::derivation
