#include "lrchain/derivation/multiscale.hpp"

#include <sstream>
#include <stdexcept>

#include "lrchain/derivation/derivation_stop.hpp"
#include "lrchain/derivation/linear_algebra.hpp"
#include "lrchain/derivation/residual.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

std::string str(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

// Coefficient of a monomial in jets (all other jets set to zero).
ex monomial_coeff(const ex& e, const std::vector<std::pair<ex, int>>& monomial, Jets& jets) {
  ex r = expand(e);
  for (const auto& [sym, deg] : monomial) r = r.coeff(sym, deg);
  exmap zero;
  for (const JetKey& key : jets.jets_in(r)) zero[jets.get(key.field, key.k, key.j, key.p, key.q)] = 0;
  return r.subs(zero, subs_options::no_pattern);
}

class Solver {
 public:
  Solver(const LatticeDescription& model, const Symbols& s, const ex& left_scale)
      : model_(model), s_(s), jets_(model.fields), n_(model.fields.size()), left_scale_(left_scale) {
    residual_ = build_residual(model, s, jets_);
  }

  DerivedCoefficients run();

 private:
  // Residual of each equation at eps^k E^j with everything known substituted.
  std::vector<ex> level(int k, int j) {
    std::vector<ex> r;
    poll_derivation_stop();  // between the orders of the expansion
    for (std::size_t f = 0; f < n_; ++f)
      r.push_back(reduce_trig(residual_[f][k][j + kMaxOrder].subs(known_, subs_options::no_pattern), s_));
    return r;
  }
  // Splits the level residual into L * (unknowns) - rhs.
  void split(int k, int j, const std::vector<ex>& res, matrix& L, std::vector<ex>& rhs) {
    L = matrix(n_, n_);
    rhs.assign(n_, 0);
    for (std::size_t i = 0; i < n_; ++i) {
      ex rest = res[i];
      for (std::size_t f = 0; f < n_; ++f) {
        const ex a = jets_.get(int(f), k, j);
        L(i, f) = rest.coeff(a, 1);
        rest = expand(rest - L(i, f) * a);
      }
      rhs[i] = -rest;
    }
  }
  // Records field values at level (k, j) and (k, -j) for every jet derivative that occurs later.
  void assign(int k, int j, const std::vector<std::pair<int, ex>>& values) {
    for (const auto& [f, value] : values) {
      for (int sign : {+1, -1}) {
        if (sign < 0 && j == 0) continue;
        const ex v = sign > 0 ? value : jets_.conjugate(value);
        for (int p = 0; p <= 1; ++p)
          for (int q = 0; q <= kMaxOrder; ++q) {
            ex d = v;
            for (int a = 0; a < p; ++a) d = jets_.d_tau(d);
            for (int b = 0; b < q; ++b) d = jets_.d_xi(d);
            known_[jets_.get(f, k, sign * j, p, q)] = expand(d);
          }
      }
    }
  }
  // Singular level: field 0 stays the free amplitude, others = kernel * free + particular solution.
  ex solve_singular(int k, int j, const matrix& L, const std::vector<ex>& rhs, const std::vector<ex>& kernel) {
    const std::vector<ex> p = particular_solution(L, rhs);
    std::vector<std::pair<int, ex>> values;
    for (std::size_t f = 1; f < n_; ++f)
      values.emplace_back(int(f), kernel[f] * jets_.get(0, k, j) + p[f]);
    assign(k, j, values);
    return 0;
  }
  // Solvability condition l . (residual) = 0 with rhs = -(residual without the unknowns).
  ex solvability(const std::vector<ex>& left, const std::vector<ex>& rhs) {
    ex s = 0;
    for (std::size_t i = 0; i < n_; ++i) s -= left[i] * rhs[i];
    return reduce_trig(s, s_);
  }
  void note(const std::string& line) {
    report_.push_back(line);
    poll_derivation_stop();
  }
  // Regular level: every field solved directly, A_{k,j} = L^{-1} rhs.
  void solve_regular(int k, int j, const matrix& L, const std::vector<ex>& rhs) {
    const matrix Linv = L.inverse();
    std::vector<std::pair<int, ex>> values;
    for (std::size_t f = 0; f < n_; ++f) {
      ex v = 0;
      for (std::size_t i = 0; i < n_; ++i) v += Linv(f, i) * rhs[i];
      values.emplace_back(int(f), normal(v));
    }
    assign(k, j, values);
  }
  // Left null vector, multiplied by the check's scale factor when one is given.
  std::vector<ex> left_null_vector(const matrix& L) {
    std::vector<ex> v = null_vector(L, /*right=*/false);
    if (!left_scale_.is_equal(1))
      for (auto& e : v) e = e * left_scale_;
    return v;
  }
  const LatticeDescription& model_;
  const Symbols& s_;
  Jets jets_;
  std::size_t n_;
  ex left_scale_;
  Residual residual_;
  exmap known_;
  std::vector<std::string> report_;
};

DerivedCoefficients Solver::run() {
  DerivedCoefficients d;
  d.model = &model_;
  matrix L;
  std::vector<ex> rhs;
  const ex A10 = jets_.get(0, 1, 0), A11 = jets_.get(0, 1, 1), A1m1 = jets_.get(0, 1, -1);

  // eps^0: nothing may remain (the equilibrium is a solution).
  for (int j = -kMaxOrder; j <= kMaxOrder; ++j)
    for (const ex& r : level(0, j))
      if (!r.is_zero()) throw std::runtime_error("eps^0 residual does not vanish: " + str(r));

  // eps^1 E^0: L_0 singular (translation mode; fields follow the kernel) or regular (on-site: A_{1,0} = 0).
  split(1, 0, level(1, 0), L, rhs);
  std::vector<ex> kernel0, left0;
  d.mean_flow = normal(L.determinant()).is_zero();
  if (d.mean_flow) {
    kernel0 = null_vector(L, /*right=*/true);
    left0 = left_null_vector(L);
    if (!solvability(left0, rhs).is_zero()) throw std::runtime_error("eps E^0 solvability fails");
    solve_singular(1, 0, L, rhs, kernel0);
    note("eps^1 E^0: L_0 singular, mean-flow kernel " + str(lst(kernel0.begin(), kernel0.end())));
  } else {
    solve_regular(1, 0, L, rhs);
    note("eps^1 E^0: L_0 regular (on-site model): A_{1,0} = 0, no mean flow");
  }

  // eps^1 E^1: M (eq:M) and the dispersion relation det M = 0 (eq:disp1d).
  split(1, 1, level(1, 1), L, rhs);
  d.dispersion = normal(L.determinant());
  d.kernel = null_vector(L, true);
  d.left_kernel = left_null_vector(L);
  solve_singular(1, 1, L, rhs, d.kernel);
  const matrix L1 = L;
  note("eps^1 E^1: dispersion relation det L_1 = " + str(d.dispersion) + " = 0");
  note("eps^1 E^1: kernel (B_{1,1}/A_{1,1} etc.) " + str(lst(d.kernel.begin(), d.kernel.end())) +
       ", left kernel " + str(lst(d.left_kernel.begin(), d.left_kernel.end())));

  // eps^2 E^0: solvability must hold identically (mean flow); solved directly (on-site).
  split(2, 0, level(2, 0), L, rhs);
  if (d.mean_flow) {
    const ex s20 = solvability(left0, rhs);
    if (!normal(s20).is_zero()) throw std::runtime_error("eps^2 E^0 solvability fails: " + str(s20));
    solve_singular(2, 0, L, rhs, kernel0);
    note("eps^2 E^0: solvability holds identically");
  } else {
    solve_regular(2, 0, L, rhs);
    note("eps^2 E^0: mean correction A_{2,0} solved directly");
  }
  // A_{2,0,f} = (free part) + offset |A_{1,1}|^2 + strain_offset d_xi A_{1,0}.
  std::vector<ex> mean_offset(n_, 0), mean_strain_offset(n_, 0);
  for (std::size_t f = d.mean_flow ? 1 : 0; f < n_; ++f) {
    const ex value = known_.at(jets_.get(int(f), 2, 0));
    const ex free_part = d.mean_flow ? kernel0[f] * jets_.get(0, 2, 0) : ex(0);
    mean_offset[f] = normal(monomial_coeff(value, {{A11, 1}, {A1m1, 1}}, jets_));
    if (d.mean_flow) mean_strain_offset[f] = normal(monomial_coeff(value, {{jets_.get(0, 1, 0, 0, 1), 1}}, jets_));
    const ex rest = value - free_part - mean_offset[f] * A11 * A1m1 - mean_strain_offset[f] * jets_.get(0, 1, 0, 0, 1);
    if (!normal(expand(rest)).is_zero()) throw std::runtime_error("eps^2 E^0 solution has unexpected terms: " + str(rest));
  }

  // eps^2 E^1: solvability fixes the group velocity c (eq:c).
  split(2, 1, level(2, 1), L, rhs);
  const ex s21 = solvability(d.left_kernel, rhs);
  const ex a_xi = monomial_coeff(s21, {{jets_.get(0, 1, 1, 0, 1), 1}}, jets_);
  if (!normal(expand(s21 - a_xi * jets_.get(0, 1, 1, 0, 1))).is_zero())
    throw std::runtime_error("eps^2 E^1 solvability has unexpected terms");
  d.group_velocity = normal(lsolve(a_xi == 0, s_.c));
  solve_singular(2, 1, L, rhs, d.kernel);
  // A_{2,1,f} = K_f A_{2,1} + gradient_f d_xi A_{1,1} (field 0: A_{2,1} free, set to 0 in an ansatz).
  d.kernel_gradient.assign(1, 0);
  for (std::size_t f = 1; f < n_; ++f) {
    const ex A11x = jets_.get(0, 1, 1, 0, 1);
    const ex value = known_.at(jets_.get(int(f), 2, 1));
    d.kernel_gradient.push_back(normal(monomial_coeff(value, {{A11x, 1}}, jets_)));
    if (!normal(expand(value - d.kernel[f] * jets_.get(0, 2, 1) - d.kernel_gradient.back() * A11x)).is_zero())
      throw std::runtime_error("eps^2 E^1 solution has unexpected terms: " + str(value));
  }
  note("eps^2 E^1: solvability (" + str(normal(a_xi)) + ") d_xi A_{1,1} = 0 gives c = " + str(d.group_velocity));

  // eps^2 E^2: second harmonic, invertible under (eq:nonresonance1).
  split(2, 2, level(2, 2), L, rhs);
  d.nonresonance1 = normal(-L.determinant());
  solve_regular(2, 2, L, rhs);
  note("eps^2 E^2: non-resonance value -det L_2 = " + str(d.nonresonance1));
  for (std::size_t f = 0; f < n_; ++f) {
    const ex value = known_.at(jets_.get(int(f), 2, 2));
    d.second_harmonic.push_back(normal(monomial_coeff(value, {{A11, 2}}, jets_)));
    if (!normal(expand(value - d.second_harmonic.back() * A11 * A11)).is_zero())
      throw std::runtime_error("eps^2 E^2 solution is not proportional to A_{1,1}^2: " + str(value));
  }

  // eps^3 E^0: mean-flow equation (eq:mod2) -> nonresonance2 and lambda (eq:lambda).
  if (d.mean_flow) {
    split(3, 0, level(3, 0), L, rhs);
    const ex s30 = solvability(left0, rhs);
    const ex A10xx = jets_.get(0, 1, 0, 0, 2);
    const ex A11x = jets_.get(0, 1, 1, 0, 1), A1m1x = jets_.get(0, 1, -1, 0, 1);
    const ex a = monomial_coeff(s30, {{A10xx, 1}}, jets_);
    const ex b1 = monomial_coeff(s30, {{A1m1, 1}, {A11x, 1}}, jets_);
    const ex b2 = monomial_coeff(s30, {{A11, 1}, {A1m1x, 1}}, jets_);
    const ex rest = normal(expand(s30 - a * A10xx - b1 * A1m1 * A11x - b2 * A11 * A1m1x));
    if (!rest.is_zero()) throw std::runtime_error("eps^3 E^0 mean flow has unexpected terms: " + str(rest));
    if (!normal(b1 - b2).is_zero()) throw std::runtime_error("mean-flow forcing is not d_xi |A_{1,1}|^2");
    d.nonresonance2 = normal(a);
    d.lambda_n2 = normal(-b1);
    note("eps^3 E^0: (" + str(d.nonresonance2) + ") d_xi^2 A_{1,0} = " + str(d.lambda_n2) + " d_xi |A_{1,1}|^2");
  } else {
    d.nonresonance2 = 1;
    d.lambda_n2 = 0;
  }

  // eps^3 E^1: solvability gives the NLS (eq:mod1).
  split(3, 1, level(3, 1), L, rhs);
  {
    const ex s31 = solvability(d.left_kernel, rhs);
    const ex A11t = jets_.get(0, 1, 1, 1, 0), A11xx = jets_.get(0, 1, 1, 0, 2);
    const ex A10x = jets_.get(0, 1, 0, 0, 1), A21x = jets_.get(0, 2, 1, 0, 1);
    const ex a_tau = monomial_coeff(s31, {{A11t, 1}}, jets_);
    const ex a_xixi = monomial_coeff(s31, {{A11xx, 1}}, jets_);
    const ex a_nl = monomial_coeff(s31, {{A11, 2}, {A1m1, 1}}, jets_);
    const ex a_beta = monomial_coeff(s31, {{A10x, 1}, {A11, 1}}, jets_);
    const ex a_21 = monomial_coeff(s31, {{A21x, 1}}, jets_);
    const ex rest = normal(expand(s31 - a_tau * A11t - a_xixi * A11xx - a_nl * A11 * A11 * A1m1 -
                                  a_beta * A10x * A11 - a_21 * A21x));
    if (!rest.is_zero()) throw std::runtime_error("eps^3 E^1 solvability has unexpected terms: " + str(rest));
    d.vanishing_modulo_dispersion.push_back(normal(a_21));
    note("eps^3 E^1: coefficient of d_xi A_{2,1} (must vanish once c is the group velocity): " + str(normal(a_21)));
    // Normalise to i d_tau A + beta d_xi A_{1,0} A + omega''/2 d_xi^2 A - h |A|^2 A = 0:
    // multiply by i/a_tau = -gamma/2 with gamma = -2i/a_tau.
    d.gamma = normal(-2 * I / a_tau);
    d.curvature_over_gamma = normal(-a_xixi);
    d.beta_over_gamma = normal(-a_beta / 2);
    d.h_n1_over_gamma = normal(a_nl / 2 * d.nonresonance1);
  }
  // Real-valuedness of every coefficient (conjugation must leave it unchanged).
  for (const ex& e : {d.gamma, d.curvature_over_gamma, d.beta_over_gamma, d.h_n1_over_gamma,
                      d.nonresonance1, d.nonresonance2, d.lambda_n2, d.group_velocity})
    if (!normal(e - jets_.conjugate(e)).is_zero()) d.imaginary_parts.push_back(e - jets_.conjugate(e));
  note("coefficients invariant under conjugation (modulo sigma^2 = D1 - D1^2/4 where listed in imaginary_parts)");

  d.curvature = explicit_form(d, s_, s_.gamma * d.curvature_over_gamma);
  d.beta = explicit_form(d, s_, s_.gamma * d.beta_over_gamma);
  d.h = explicit_form(d, s_, s_.gamma * d.h_n1_over_gamma / d.nonresonance1);
  d.lambda = explicit_form(d, s_, d.lambda_n2 / d.nonresonance2);
  d.h_tilde = d.h - d.lambda * d.beta;
  for (std::size_t f = 0; f < n_; ++f) {
    d.second_harmonic[f] = explicit_form(d, s_, d.second_harmonic[f]);
    d.kernel_gradient[f] = explicit_form(d, s_, d.kernel_gradient[f]);
    d.mean_offset.push_back(explicit_form(d, s_, mean_offset[f]) +
                            (d.mean_flow ? explicit_form(d, s_, mean_strain_offset[f]) * d.lambda : ex(0)));
  }
  d.h_tilde_numerator = explicit_form(
      d, s_, s_.gamma * d.h_n1_over_gamma * d.nonresonance2 - d.lambda_n2 * s_.gamma * d.beta_over_gamma * d.nonresonance1);
  d.report = report_;
  (void)L1;
  return d;
}

}  // namespace

ex explicit_form(const DerivedCoefficients& d, const Symbols& s, const ex& e) {
  return e.subs(lst{s.gamma == d.gamma}).subs(lst{s.c == d.group_velocity});
}

DerivedCoefficients derive(const LatticeDescription& model, const Symbols& s, const ex& left_kernel_scale) {
  return Solver(model, s, left_kernel_scale).run();
}

}  // namespace lrchain::derivation
