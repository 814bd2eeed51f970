#include "lrchain/derivation/model_emission.hpp"

#include <cstdint>
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

#include "lrchain/derivation/branches.hpp"
#include "lrchain/derivation/c_string_literal.hpp"
#include "lrchain/derivation/derivation_stop.hpp"
#include "lrchain/derivation/emit_cpp.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

// A real expression that GiNaC holds with complex numbers (complex Bloch kernels) as a ratio of
// real polynomials: times the conjugate denominator, reduced modulo sigma^2 = D1 - D1^2/4, real part.
ex real_form(const ex& e, const Symbols& s) {
  if (!e.has(I)) return e;
  const ex nd = normal(e).numer_denom();
  const ex relation = pow(s.sigma, 2) - s.D1 + pow(s.D1, 2) / 4;
  const auto reduced = [&](const ex& p) { return expand(rem(expand(p), relation, s.sigma)); };
  const ex conjugate_denominator = nd.op(1).conjugate();
  const ex numerator = expand(nd.op(0) * conjugate_denominator), denominator = expand(nd.op(1) * conjugate_denominator);
  if (!reduced(numerator.imag_part()).is_zero() || !reduced(denominator.imag_part()).is_zero())
    throw std::runtime_error("a coefficient is not real modulo sigma^2 = D1 - D1^2/4");
  return reduced(numerator.real_part()) / reduced(denominator.real_part());
}

// q[i] for every parameter, then every named intermediate (the order of LatticeDescription::parameters).
std::vector<std::pair<ex, std::string>> q_inputs(const ModelDerivation& m) {
  std::vector<std::pair<ex, std::string>> inputs;
  for (std::size_t i = 0; i < m.file.model.parameters.size(); ++i)
    inputs.emplace_back(m.file.model.parameters[i], "q[" + std::to_string(i) + "]");
  return inputs;
}

// e factored as a polynomial in its parameters, its non-rational parts (delta0^alpha) held as
// symbols meanwhile: Hertz's K4 = alpha (alpha - 1) (alpha - 2) delta0^alpha / (6 delta0^3) as the
// expanded sum of its alpha^3, alpha^2 and alpha terms cancels near alpha = 2 (K4's relative error
// up to 8e-12 at alpha = 1.99995, carried into h on the optical branch at small theta).
ex factored_intermediate(const ex& e) {
  exmap non_rational;
  const ex rational = e.to_rational(non_rational);
  const ex nd = normal(rational).numer_denom();
  return (factor(nd.op(0)) / factor(nd.op(1))).subs(non_rational, subs_options::no_pattern);
}

// q = parameters followed by the named intermediates evaluated from them.
EmittedFunction intermediates_function(const ModelDerivation& m) {
  EmittedFunction f;
  f.name = "intermediates";
  f.comment = "q = the parameters p, then the named intermediates of the force laws.";
  f.parameter_list = "const double* p, double* q";
  const std::size_t n = m.file.parameters.size();
  for (std::size_t i = 0; i < n; ++i) {
    f.inputs.emplace_back(m.file.parameters[i].symbol, "p[" + std::to_string(i) + "]");
    f.prologue += "  q[" + std::to_string(i) + "] = p[" + std::to_string(i) + "];\n";
  }
  for (std::size_t j = 0; j < m.file.intermediates.size(); ++j) {
    const std::string name = "q[" + std::to_string(n + j) + "]";
    f.outputs.emplace_back(name, factored_intermediate(m.file.intermediates[j].value));
  }
  return f;
}

// Coefficients of det M (numerator of the dispersion relation) in powers of omega^2.
EmittedFunction dispersion_function(const ModelDerivation& m, const Symbols& s) {
  EmittedFunction f;
  f.name = "dispersion";
  f.comment = "Coefficients of det M = 0 in ascending powers of omega^2 at D1 = 4 sin^2(theta/2), sigma = sin(theta).";
  f.parameter_list = "double D1, double sigma, const double* q, double* w";
  f.inputs = {{s.D1, "D1"}, {s.sigma, "sigma"}};
  for (const auto& input : q_inputs(m)) f.inputs.push_back(input);
  const ex polynomial = expand(numer(normal(m.coefficients.dispersion)));
  const int degree = polynomial.degree(s.omega);
  for (int k = 0; k <= degree; ++k) {
    const ex c = polynomial.coeff(s.omega, k);
    if (k % 2) {
      if (!normal(c).is_zero()) throw std::runtime_error("det M has an odd power of omega");
      continue;
    }
    f.outputs.emplace_back("w[" + std::to_string(k / 2) + "]", real_form(c, s));
  }
  f.prologue = "  (void)sigma;\n  (void)q;\n";
  return f;
}

// The named intermediates in long double from long double parameters (std::pow on long double),
// for the extended-precision nls: the rounding of q to double would be amplified where a
// coefficient crosses zero as the intermediates vary (h of newtons_cradle).
EmittedFunction intermediates_extended_function(const ModelDerivation& m) {
  EmittedFunction f = intermediates_function(m);
  f.name = "intermediates_extended";
  f.comment = "intermediates() in long double.";
  f.parameter_list = "const long double* p, long double* q";
  f.real_type = "long double";
  f.prologue = "  using real [[maybe_unused]] = long double;\n" + f.prologue;
  return f;
}

// The inputs q[i] read as Q[i] in the type `real`: the parameters as given, the intermediates
// recomputed from them in long double (else converted from q's doubles); declared by the returned statements.
std::string extended_q(EmittedFunction& f, const ModelDerivation& m, bool recompute_intermediates) {
  for (auto& [symbol, name] : f.inputs)
    if (name.rfind("q[", 0) == 0) name = "Q" + name.substr(1);
  const std::string n = std::to_string(m.file.parameters.size());
  const std::string all = std::to_string(m.file.model.parameters.size());
  if (!recompute_intermediates)
    return "  real Q[" + all + "];\n"
           "  lrchain::model_evaluator::widen(q, Q, " + all + ");\n";
  return "  long double parameters[" + n + "], intermediates[" + all + "];\n"
         "  lrchain::model_evaluator::widen(q, parameters, " + n + ");\n"
         "  intermediates_extended(parameters, intermediates);\n"
         "  real Q[" + all + "];\n"
         "  lrchain::model_evaluator::widen(intermediates, Q, " + all + ");\n";
}

// det M's coefficients in `real_type` at D1, sigma, Q of that type (used by the extended-precision nls).
EmittedFunction dispersion_extended_function(const ModelDerivation& m, const Symbols& s, const std::string& real_type) {
  EmittedFunction f = dispersion_function(m, s);
  f.name = "dispersion_extended";
  f.comment = "Coefficients of det M as dispersion(), in " + real_type + " arithmetic.";
  f.parameter_list = real_type + " D1, " + real_type + " sigma, const " + real_type + "* Q, " + real_type + "* w";
  f.real_type = real_type;
  for (auto& [symbol, name] : f.inputs)
    if (name.rfind("q[", 0) == 0) name = "Q" + name.substr(1);
  f.prologue = "  using real [[maybe_unused]] = " + real_type + ";\n  (void)sigma;\n  (void)Q;\n";
  return f;
}

// Statements that turn the double inputs D1_in, sigma_in, omega_in into D1, sigma, omega in the type
// `real`, consistent to that precision (lrchain/model_evaluator_support.hpp): sin^2 + cos^2 = 1 for the
// half angle and det M = 0 (omega^2 polished by Newton steps).
std::string consistent_inputs(int degree) {
  return "  // D1, sigma and omega consistent in `real` (sin^2 + cos^2 = 1 for theta/2, det M = 0).\n"
         "  real D1, sigma;\n"
         "  lrchain::model_evaluator::consistent_half_angle(D1_in, sigma_in, D1, sigma);\n"
         "  real w[" + std::to_string(degree + 1) + "];\n"
         "  dispersion_extended(D1, sigma, Q, w);\n"
         "  const real omega = lrchain::model_evaluator::polished_omega(w, " + std::to_string(degree) + ", omega_in);\n";
}

// The NLS coefficients in derivation order, later ones written with earlier ones by name; in
// `real_type` arithmetic from consistent inputs when that is not double (model_evaluator_precision).
EmittedFunction nls_function(const ModelDerivation& m, const Symbols& s, const std::string& real_type,
                             bool recompute_intermediates = true) {
  const DerivedCoefficients& c = m.coefficients;
  EmittedFunction f;
  f.name = "nls";
  f.comment = "NLS coefficients at omega on a branch of det M = 0 (outputs in lrchain::ModelOutput order).";
  f.parameter_list = "double D1, double sigma, double omega, const double* q, double* out";
  f.inputs = {{s.D1, "D1"}, {s.sigma, "sigma"}, {s.omega, "omega"}};
  for (const auto& input : q_inputs(m)) f.inputs.push_back(input);
  const realsymbol beta("beta"), n1("nonresonance1"), n2("nonresonance2"), h("h"), lambda("lambda");
  f.output_symbols = {{"out[0]", s.c}, {"out[1]", s.gamma}, {"out[3]", beta}, {"out[4]", n1},
                      {"out[5]", n2},  {"out[6]", h},       {"out[7]", lambda}};
  f.outputs = {
      {"out[0]", c.group_velocity},
      {"out[1]", c.gamma},
      {"out[2]", s.gamma * c.curvature_over_gamma},
      {"out[3]", s.gamma * c.beta_over_gamma},
      {"out[4]", c.nonresonance1},
      {"out[5]", c.nonresonance2},
      {"out[6]", s.gamma * c.h_n1_over_gamma / n1},
      {"out[7]", c.lambda_n2 / n2},
      {"out[8]", h - lambda * beta},
      {"out[9]", s.gamma * c.h_n1_over_gamma * n2 - c.lambda_n2 * beta * n1},
      {"out[10]", c.dispersion},
      {"out[11]", c.nonresonance1},
      {"out[12]", c.nonresonance2},
  };
  for (auto& [name, e] : f.outputs) e = real_form(e, s);
  f.term_scales = {"out[11]", "out[12]"};
  if (real_type == "double") {
    f.prologue = "  (void)sigma;\n  (void)q;\n";
    return f;
  }
  const std::string count = std::to_string(f.outputs.size());
  f.real_type = real_type;
  f.parameter_list = "double D1_in, double sigma_in, double omega_in, const double* q, double* out";
  f.local_outputs = "o";
  f.abs_function = "magnitude";
  f.prologue = "  using real [[maybe_unused]] = " + real_type + ";\n"
               "  using lrchain::model_evaluator::magnitude;\n" + extended_q(f, m, recompute_intermediates) +
               consistent_inputs(int(m.branches.size())) + "  real o[" + count + "];\n";
  f.epilogue = "  for (int k = 0; k < " + count + "; ++k) out[k] = static_cast<double>(o[k]);\n";
  return f;
}

// Real and imaginary parts of a derived expression held with complex numbers (complex Bloch
// kernels), each a ratio of real polynomials reduced modulo sigma^2 = D1 - D1^2/4 (as real_form).
std::pair<ex, ex> complex_parts(const ex& e, const Symbols& s) {
  if (!e.has(I)) return {e, 0};
  const ex nd = normal(e).numer_denom();
  const ex relation = pow(s.sigma, 2) - s.D1 + pow(s.D1, 2) / 4;
  const auto reduced = [&](const ex& p) { return expand(rem(expand(p), relation, s.sigma)); };
  const ex conjugate_denominator = nd.op(1).conjugate();
  const ex numerator = expand(nd.op(0) * conjugate_denominator), denominator = expand(nd.op(1) * conjugate_denominator);
  if (!reduced(denominator.imag_part()).is_zero()) throw std::runtime_error("|denominator|^2 is not real");
  const ex real_denominator = reduced(denominator.real_part());
  return {reduced(numerator.real_part()) / real_denominator, reduced(numerator.imag_part()) / real_denominator};
}

// The second-order terms per field f at out[5 f + lrchain::HarmonicOutput]: the second harmonic
// A_{2,2,f} / A_{1,1}^2 (real, imaginary part), the mean A_{2,0,f} / |A_{1,1}|^2 and the gradient
// term of A_{2,1,f} per unit d_xi A_{1,1} (real, imaginary part), in `real_type`
// from consistent inputs (as the extended nls; not a hot path: an ansatz calls it once).
EmittedFunction harmonics_function(const ModelDerivation& m, const Symbols& s, const std::string& real_type,
                                   bool recompute_intermediates) {
  const DerivedCoefficients& c = m.coefficients;
  EmittedFunction f;
  f.name = "harmonics";
  f.comment = "Per field f, out[5f..5f+4]: second harmonic A_{2,2,f}/A_{1,1}^2 (real, imaginary part), mean "
              "A_{2,0,f}/|A_{1,1}|^2, gradient term of A_{2,1,f} per d_xi A_{1,1} (real, imaginary) (lrchain::HarmonicOutput).";
  f.parameter_list = "double D1, double sigma, double omega, const double* q, double* out";
  f.inputs = {{s.D1, "D1"}, {s.sigma, "sigma"}, {s.omega, "omega"}};
  for (const auto& input : q_inputs(m)) f.inputs.push_back(input);
  for (std::size_t field = 0; field < c.second_harmonic.size(); ++field) {
    const auto [real_part, imaginary_part] = complex_parts(c.second_harmonic[field], s);
    f.outputs.emplace_back("out[" + std::to_string(5 * field) + "]", real_part);
    f.outputs.emplace_back("out[" + std::to_string(5 * field + 1) + "]", imaginary_part);
    f.outputs.emplace_back("out[" + std::to_string(5 * field + 2) + "]", real_form(c.mean_offset[field], s));
    const auto [gradient_real, gradient_imaginary] = complex_parts(c.kernel_gradient[field], s);
    f.outputs.emplace_back("out[" + std::to_string(5 * field + 3) + "]", gradient_real);
    f.outputs.emplace_back("out[" + std::to_string(5 * field + 4) + "]", gradient_imaginary);
  }
  if (real_type == "double") {
    f.prologue = "  (void)sigma;\n  (void)q;\n";
    return f;
  }
  const std::string count = std::to_string(f.outputs.size());
  f.real_type = real_type;
  f.parameter_list = "double D1_in, double sigma_in, double omega_in, const double* q, double* out";
  f.local_outputs = "o";
  f.prologue = "  using real [[maybe_unused]] = " + real_type + ";\n"
               "  [[maybe_unused]] const auto magnitude = [](real x) { return x < 0 ? -x : x; };\n" + extended_q(f, m, recompute_intermediates) +
               consistent_inputs(int(m.branches.size())) + "  real o[" + count + "];\n";
  f.epilogue = "  for (int k = 0; k < " + count + "; ++k) out[k] = static_cast<double>(o[k]);\n";
  return f;
}

// Below this D1 (theta < 0.05) the double nls hands over to its long double version: there the
// acoustic omega'' = (W'' - 2 c^2) / (2 omega), W = omega^2, loses digits as 1/theta^2 (measured on
// the resonant chain over its sampled parameters: 6.6e-12 at theta = 0.02, 9.3e-13 at 0.05, 2.3e-13 at 0.1).
constexpr const char* double_nls_extended_below = "0.0025";

// A double nls that hands its inputs to nls_extended where its sums cancel by more than this factor
// (error about 1e-16 times it): near a zero of h or h_tilde, or near a non-resonance violation.
// (Checking omega'' too cost 5 ns per call; 1e3 instead of 1e4 sent the paper's acoustic branch
// near h = 0 to long double 20 times per 1024 points: both measured below 10 M/s.)
constexpr const char* double_nls_cancellation_limit = "1e4";

// p or -p, whichever is positive at a point fixed by the symbols' names (factor() returns either
// sign from one run to the next; the emitted text must not change).
ex canonical_sign(const ex& p) {
  exmap point;
  for (const_preorder_iterator i = p.preorder_begin(); i != p.preorder_end(); ++i)
    if (is_a<symbol>(*i)) {
      std::uint64_t hash = 1469598103934665603ull;
      for (const char ch : ex_to<symbol>(*i).get_name()) hash = (hash ^ std::uint8_t(ch)) * 1099511628211ull;
      point[*i] = numeric(long(1000 + hash % 1000u), 997);
    }
  const ex value = p.subs(point, subs_options::no_pattern);
  return is_a<numeric>(value) && ex_to<numeric>(value).is_negative() ? ex(-p) : p;
}

// Adds to the double nls f the magnitudes of the terms of h's numerator, and an epilogue that
// re-evaluates in long double (nls_extended) where h's numerator or a non-resonance value, times
// the cancellation of h_tilde = h - lambda beta (which multiplies their rounding errors), cancels
// by more than double_nls_cancellation_limit (each alone passed: h_tilde lost 1.3e-11 at 82 x 3900).
EmittedFunction with_cancellation_check(EmittedFunction f, const ModelDerivation& m) {
  const std::pair<std::string, std::string> checked[] = {{"h", "out[6]"}};
  std::string condition;
  for (const auto& [quantity, output] : checked)
    for (const auto& [name, e] : std::vector<std::pair<std::string, ex>>(f.outputs))
      if (name == output) {
        // The sum among the factors of the numerator (printed as in the output, so its terms are shared).
        const ex numerator = factor(normal(e).numer_denom().op(0));
        ex sum = numerator;
        if (is_a<GiNaC::mul>(numerator))
          for (const auto& factor_term : numerator)
            if (is_a<GiNaC::add>(factor_term)) sum = factor_term;
        if (!is_a<GiNaC::add>(sum)) continue;  // a product: nothing cancels
        sum = canonical_sign(expand(sum / sum.integer_content()));  // primitive, as emit_cpp prints factors
        const std::string value = "sum_" + quantity, scale = "cancellation_" + quantity;
        f.outputs.emplace_back(value, sum);
        f.outputs.emplace_back(scale, sum);
        f.term_scales.insert(scale);
        f.prologue += "  double " + value + ", " + scale + ";\n";
        condition += std::string(condition.empty() ? "" : " &&\n        ") + "std::abs(" + value + ") * bound > " + scale +
                     " * terms";
      }
  condition += " &&\n        std::abs(out[4]) * bound > out[11] * terms";
  std::string bound = "  const double bound = limit, terms = 1;\n";
  if (m.coefficients.mean_flow) {
    // h_tilde = h - lambda beta multiplies the relative errors of h and lambda by its own cancellation.
    condition += " && std::abs(out[5]) * bound > out[12] * terms";
    bound = "  const double bound = std::abs(out[8]) * limit, terms = std::abs(out[6]) + std::abs(out[3] * out[7]);\n";
  }
  f.epilogue += "  // Sums that cancel in double (near a zero of h, or a non-resonance, times the cancellation of\n"
                "  // h_tilde): long double.\n"
                "  const double limit = " + std::string(double_nls_cancellation_limit) + ";\n" + bound +
                "  if (!(" + condition + "))\n"
                "    nls_extended(D1, sigma, omega, q, out);\n";
  return f;
}

// The double nls with omega'' by implicit differentiation of det M = P(W, D1) = 0 at W = omega^2,
// D1' = 2 sigma, D1'' = 2 - D1, from P's partial derivatives evaluated as numbers: the closed form
// of omega'' divides by powers of a factor of P's D1-derivative that vanishes on the acoustic branch
// near theta = pi (its expanded terms cancel by up to 1e6 there); this form has no such division.
// Points with D1 below double_nls_extended_below are passed to nls_extended (same inputs).
EmittedFunction double_nls_function(const ModelDerivation& m, const Symbols& s) {
  EmittedFunction f = nls_function(m, s, "double");
  f.prologue = "  if (D1 < " + std::string(double_nls_extended_below) + ") {\n"
               "    nls_extended(D1, sigma, omega, q, out);\n"
               "    return;\n"
               "  }\n" + f.prologue;
  const realsymbol W("W");
  const ex polynomial = expand(numer(normal(m.coefficients.dispersion)));
  ex P = 0;
  for (int k = 0; k <= polynomial.degree(s.omega); k += 2) P += real_form(polynomial.coeff(s.omega, k), s) * pow(W, k / 2);
  if (P.has(s.sigma)) return with_cancellation_check(f, m);  // det M depends on sigma: keep the closed form
  const std::pair<std::string, ex> derivatives[] = {
      {"dispersion_W", P.diff(W)},          {"dispersion_D", P.diff(s.D1)},         {"dispersion_WW", P.diff(W, 2)},
      {"dispersion_WD", P.diff(W).diff(s.D1)}, {"dispersion_DD", P.diff(s.D1, 2)}};
  std::vector<std::pair<std::string, ex>> locals;
  std::vector<ex> value;
  std::string declared;
  for (const auto& [name, d] : derivatives) {
    const ex at_omega = expand(d.subs(W == pow(s.omega, 2)));
    if (is_a<numeric>(at_omega)) {
      value.push_back(at_omega);
      continue;
    }
    const realsymbol local(name);
    f.output_symbols[name] = local;
    locals.emplace_back(name, at_omega);
    value.push_back(local);
    declared += (declared.empty() ? "  double " : ", ") + name;
  }
  f.prologue += declared + ";\n";
  const ex dW = 2 * s.omega * s.c, dD1 = 2 * s.sigma, ddD1 = 2 - s.D1;
  const ex ddW = -(value[2] * dW * dW + 2 * value[3] * dW * dD1 + value[4] * dD1 * dD1 + value[1] * ddD1) / value[0];
  const ex curvature = (ddW - 2 * pow(s.c, 2)) / (2 * s.omega);
  for (std::size_t k = 0; k < f.outputs.size(); ++k) {
    if (f.outputs[k].first != "out[2]") continue;
    f.outputs[k].second = curvature;
    f.outputs.insert(f.outputs.begin() + std::ptrdiff_t(k), locals.begin(), locals.end());
    break;
  }
  f.comment += " omega'' by implicit differentiation of det M; theta < 0.05 in long double (nls_extended).";
  return with_cancellation_check(f, m);
}

std::string number_text(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

}  // namespace

double evaluator_cancellation(const ModelDerivation& m, const Symbols& s) {
  const EmittedFunction f = nls_function(m, s, "double");
  // The factors emit_cpp prints: factor(numerator), factor(denominator), each expanded.
  std::vector<std::pair<std::string, std::vector<ex>>> factored;
  for (const auto& [name, e] : f.outputs) {
    poll_derivation_stop();
    std::vector<ex> polynomials;
    // Not det M (zero on the branch by construction) nor the term scales (sums of magnitudes).
    if (name != "out[10]" && !f.term_scales.count(name)) {
      const ex nd = normal(e).numer_denom();
      for (int side = 0; side < 2; ++side) {
        const ex polynomial = expand(nd.op(side));
        if (is_a<GiNaC::add>(polynomial)) polynomials.push_back(polynomial);
      }
    }
    factored.emplace_back(name, polynomials);
  }
  double worst = 1;
  for (std::size_t branch = 0; branch < m.branches.size(); ++branch) {
    if (!m.branches[branch].real) continue;
    for (const double theta : {0.001 * M_PI, 0.01 * M_PI, 0.3 * M_PI, 0.7 * M_PI, 0.99 * M_PI, 0.999 * M_PI}) {
      exmap point;
      try {
        point = BranchPoint(m.coefficients, s, m.values, theta, branch, 40).substitutions();
      } catch (const std::runtime_error&) {
        continue;  // no positive frequency there
      }
      for (std::size_t k = 0; k < f.outputs.size(); ++k) {
        for (const ex& polynomial : factored[k].second) {
          numeric total = 0;
          for (const ex& term : polynomial) total += abs(ex_to<numeric>(evalf(term.subs(point, subs_options::no_pattern))));
          const numeric value = abs(ex_to<numeric>(evalf(polynomial.subs(point, subs_options::no_pattern))));
          if (!value.is_zero()) worst = std::max(worst, (total / value).to_double());
        }
        const auto symbol = f.output_symbols.find(f.outputs[k].first);
        if (symbol != f.output_symbols.end())
          point[symbol->second] = evalf(f.outputs[k].second.subs(point, subs_options::no_pattern));
      }
    }
  }
  return worst;
}

std::string evaluator_precision(double cancellation) {
  // 2^-64 (long double) times the cancellation must stay below 1e-12, a factor 10 under the 1e-11
  // the evaluators are tested to (errors of the shipped models measured 1 to 20 times this product);
  // else __float128 (2^-113).
  return cancellation * 5.4e-20 <= 1e-12 ? "long double" : "__float128";
}

std::vector<EmittedFunction> model_evaluator_definitions(const ModelDerivation& m, const Symbols& s) {
  return {intermediates_function(m), dispersion_function(m, s), nls_function(m, s, "double"),
          harmonics_function(m, s, "double", true)};
}

std::string model_evaluator_functions(const ModelDerivation& m, const Symbols& s, const std::string& arithmetic) {
  if (arithmetic == "double") {
    // The intermediates q as given (a pow per call would cost the double path its rate).
    EmittedFunction extended = nls_function(m, s, "long double", false);
    extended.name = "nls_extended";
    extended.comment = "nls() in long double from consistent inputs, where the double nls loses digits.";
    return emit_function(intermediates_function(m)) + "\n" + emit_function(dispersion_function(m, s)) + "\n" +
           emit_function(dispersion_extended_function(m, s, "long double")) + "\n" + emit_function(extended) + "\n" +
           emit_function(double_nls_function(m, s)) + "\n" + emit_function(harmonics_function(m, s, "long double", false));
  }
  const EvaluatorParts parts = model_evaluator_parts(m, s, arithmetic);
  return parts.common + parts.nls + "\n" + parts.harmonics;
}

EvaluatorParts model_evaluator_parts(const ModelDerivation& m, const Symbols& s, const std::string& arithmetic) {
  const double cancellation = evaluator_cancellation(m, s);
  const std::string real_type = arithmetic.empty() ? evaluator_precision(cancellation) : arithmetic;
  EvaluatorParts parts;
  parts.common = emit_function(intermediates_function(m)) + "\n" + emit_function(dispersion_function(m, s)) + "\n";
  if (real_type != "double")
    parts.common += emit_function(intermediates_extended_function(m)) + "\n" +
                    emit_function(dispersion_extended_function(m, s, real_type)) + "\n";
  EmittedFunction nls = nls_function(m, s, real_type);
  char measured[160];
  std::snprintf(measured, sizeof measured, " In %s: the terms of its factors cancel by up to %.2g (measured at derivation).",
                real_type.c_str(), cancellation);
  nls.comment += measured;
  parts.nls = emit_function(nls);
  parts.harmonics = emit_function(harmonics_function(m, s, real_type, true));
  return parts;
}

std::string model_definition_function(const ModelDerivation& m) {
  std::ostringstream out;
  out << "// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).\n"
         "inline lrchain::ModelDefinition definition() {\n"
         "  lrchain::ModelDefinition d;\n"
      << "  d.name = " << c_string_literal(m.file.name) << ";\n"
      << "  d.description = " << c_string_literal(m.file.description) << ";\n"
      << "  d.file_hash = " << hash_text(m.file.hash) << "ull;\n"
      << "  d.file_sha256 = " << c_string_literal(m.file.sha256) << ";\n";
  for (const auto& p : m.file.parameters) {
    const auto& r = p.range;
    out << "  d.parameters.push_back({" << c_string_literal(p.name) << ", " << c_string_literal(r.text) << ", "
        << number_text(p.default_value.to_double()) << ", " << (r.has_lower ? "true" : "false") << ", "
        << (r.has_upper ? "true" : "false") << ", " << (r.lower_closed ? "true" : "false") << ", "
        << (r.upper_closed ? "true" : "false") << ", " << (r.has_lower ? number_text(r.lower.to_double()) : "0") << ", "
        << (r.has_upper ? number_text(r.upper.to_double()) : "0") << "});\n";
  }
  for (const auto& i : m.file.intermediates) out << "  d.intermediates.push_back(" << c_string_literal(i.name) << ");\n";
  for (const auto& b : m.branches) out << "  d.branch_names.push_back(" << c_string_literal(b.name) << ");\n";
  out << "  d.mean_flow = " << (m.coefficients.mean_flow ? "true" : "false") << ";\n"
      << "  d.degree = " << m.branches.size() << ";\n"
      << "  d.evaluators = {&intermediates, &dispersion, &nls, &harmonics, nullptr};\n"
         "  return d;\n}\n";
  return out.str();
}

std::string model_header(const ModelDerivation& m, const Symbols& s, const std::string& arithmetic) {
  std::ostringstream out;
  out << "// GENERATED FILE - DO NOT EDIT.\n"
         "// Written by lrchain-derive from models/" << m.file.name << ".toml (FNV-1a 64 " << hash_text(m.file.hash)
      << "): the double evaluators of\n"
         "// the model's dispersion relation and NLS coefficients (docs/models.md).\n"
         "// Regenerate with `cmake --build build --target regenerate`.\n"
         "#pragma once\n\n#include <cmath>\n\n#include \"lrchain/model.hpp\"\n#include \"lrchain/model_evaluator_support.hpp\"\n\n"
         "namespace lrchain::generated::model_" << m.file.name << " {\n\n"
      << model_evaluator_functions(m, s, arithmetic) << "\n" << model_definition_function(m) << "\n"
      << "}  // namespace lrchain::generated::model_" << m.file.name << "\n";
  return out.str();
}

std::string shipped_models_header(const std::vector<std::string>& names) {
  std::ostringstream out;
  out << "// GENERATED FILE - DO NOT EDIT.\n"
         "// Written by lrchain-derive: the shipped models (models/*.toml) with their emitted evaluators.\n"
         "#pragma once\n\n#include <vector>\n\n";
  for (const auto& n : names) out << "#include \"lrchain/generated/model_" << n << ".hpp\"\n";
  out << "\nnamespace lrchain::generated {\n\n"
         "// Definitions of every shipped model, sorted by name.\n"
         "inline std::vector<lrchain::ModelDefinition> shipped_model_definitions() {\n"
         "  std::vector<lrchain::ModelDefinition> models;\n";
  for (const auto& n : names) out << "  models.push_back(model_" << n << "::definition());\n";
  out << "  return models;\n}\n\n}  // namespace lrchain::generated\n";
  return out.str();
}

}  // namespace lrchain::derivation
