#include "lrchain/derivation/generate.hpp"

#include <sstream>

#include "lrchain/derivation/emit_cpp.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

Derivation derive_all() {
  Derivation d;
  d.resonant = resonant_chain_model(d.symbols);
  d.homogeneous = homogeneous_chain_model(d.symbols);
  d.resonant_coefficients = derive(d.resonant, d.symbols);
  d.homogeneous_coefficients = derive(d.homogeneous, d.symbols);
  // The model pointers refer into `d`; callers keep `d` alive while using them.
  return d;
}

namespace {

// One evaluator: inputs D1, sigma, omega, model parameters; outputs in derivation order, each
// written with the earlier named results (group velocity c, gamma, beta, ...) the way the
// derivation produces them.
EmittedFunction evaluator(const DerivedCoefficients& c, const Symbols& s, const LatticeDescription& m) {
  EmittedFunction f;
  f.name = m.name + "_nls";
  f.comment = "NLS coefficients of the " + m.description + ".";
  f.result_type = "NlsValues";
  f.inputs = {{s.D1, "D1"}, {s.sigma, "sigma"}, {s.omega, "omega"}};
  for (const ex& p : m.parameters) f.inputs.emplace_back(p, ex_to<symbol>(p).get_name());
  for (const auto& input : m.emission_inputs) f.inputs.push_back(input);
  const realsymbol beta("beta"), n1("nonresonance1"), n2("nonresonance2"), h("h"), lambda("lambda");
  f.output_symbols = {{"group_velocity", s.c}, {"gamma", s.gamma}, {"beta", beta}, {"nonresonance1", n1},
                      {"nonresonance2", n2}, {"h", h}, {"lambda", lambda}};
  f.outputs = {
      {"group_velocity", c.group_velocity},
      {"gamma", c.gamma},
      {"curvature", s.gamma * c.curvature_over_gamma},
      {"beta", s.gamma * c.beta_over_gamma},
      {"nonresonance1", c.nonresonance1},
      {"nonresonance2", c.nonresonance2},
      {"h", s.gamma * c.h_n1_over_gamma / n1},
      {"lambda", c.lambda_n2 / n2},
      {"h_tilde", h - lambda * beta},
      {"h_tilde_numerator", s.gamma * c.h_n1_over_gamma * n2 - c.lambda_n2 * beta * n1},
      {"dispersion", c.dispersion},
  };
  // Each output keeps whichever form (original, or with the model's rewrites) has fewer terms
  // after factoring: fewer terms, fewer opportunities for cancellation in double precision.
  for (auto& [name, e] : f.outputs) {
    ex rewritten = e;
    for (const auto& [pattern, replacement] : m.emission_rewrites)
      rewritten = rewritten.subs(pattern == replacement, subs_options::algebraic);
    if (emitted_size(rewritten) < emitted_size(e)) e = rewritten;
  }
  return f;
}

}  // namespace

std::string generated_header(const Derivation& d) {
  std::ostringstream out;
  out << "// GENERATED FILE - DO NOT EDIT.\n"
         "// Written by lrchain-derive (derivation/, GiNaC " << GINACLIB_MAJOR_VERSION << "." << GINACLIB_MINOR_VERSION
      << ") from the multiple-scale expansion of the lattice\n"
         "// equations (eq:Hertz, eq:ansatz; Appendix A). Regenerate with `cmake --build build --target regenerate`.\n"
         "// Inputs: D1 = 4 sin^2(theta/2), sigma = sin(theta), omega on the dispersion relation, and the\n"
         "// model parameters (K2, K3, K4 from eq:expv). h and lambda divide by the non-resonance values\n"
         "// (eq:nonresonance1, eq:nonresonance2); h_tilde_numerator = h_tilde * nonresonance1 * nonresonance2\n"
         "// is smooth across those poles; dispersion = det L_1 (zero on the dispersion relation).\n"
         "#pragma once\n\n"
         "namespace lrchain::generated {\n\n"
         "struct NlsValues {\n"
         "  double group_velocity, gamma, curvature, beta, nonresonance1, nonresonance2, h, lambda, h_tilde,\n"
         "      h_tilde_numerator, dispersion;\n"
         "};\n\n";
  out << emit_function(evaluator(d.resonant_coefficients, d.symbols, d.resonant)) << "\n";
  out << emit_function(evaluator(d.homogeneous_coefficients, d.symbols, d.homogeneous)) << "\n";
  out << "}  // namespace lrchain::generated\n";
  return out.str();
}

std::string report(const Derivation& d, const std::vector<CheckResult>& checks) {
  std::ostringstream out;
  for (const auto* c : {&d.resonant_coefficients, &d.homogeneous_coefficients}) {
    out << "== " << c->model->description << "\n";
    for (const auto& line : c->report) out << "  " << line << "\n";
    out << "  c       = " << c->group_velocity << "\n"
        << "  gamma   = " << c->gamma << "\n"
        << "  omega''/gamma = " << c->curvature_over_gamma << "\n"
        << "  beta/gamma    = " << c->beta_over_gamma << "\n"
        << "  h*nonresonance1/gamma = " << c->h_n1_over_gamma << "\n"
        << "  lambda*nonresonance2  = " << c->lambda_n2 << "\n";
  }
  int passed = 0;
  out << "== checks against the paper (resonant chain; printed formulas used only as checks)\n";
  for (const auto& r : checks) {
    passed += r.passed;
    out << "  [" << (r.passed ? "PASS" : "FAIL") << "] " << r.name << "  (" << r.method << ": " << r.detail << ")\n";
  }
  out << "== " << passed << "/" << checks.size() << " checks passed\n";
  return out.str();
}

}  // namespace lrchain::derivation
