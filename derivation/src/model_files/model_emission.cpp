#include "lrchain/derivation/model_emission.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

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

// q[i] for every parameter, then every named intermediate (the order of LatticeModel::parameters).
std::vector<std::pair<ex, std::string>> q_inputs(const ModelDerivation& m) {
  std::vector<std::pair<ex, std::string>> inputs;
  for (std::size_t i = 0; i < m.file.model.parameters.size(); ++i)
    inputs.emplace_back(m.file.model.parameters[i], "q[" + std::to_string(i) + "]");
  return inputs;
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
    f.outputs.emplace_back(name, m.file.intermediates[j].value);
    f.unfactored.insert(name);
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

// The NLS coefficients in derivation order, later ones written with earlier ones by name.
EmittedFunction nls_function(const ModelDerivation& m, const Symbols& s) {
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
  f.prologue = "  (void)sigma;\n  (void)q;\n";
  return f;
}

std::string number_text(double v) {
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char ch : s) {
    if (ch == '"' || ch == '\\') out += '\\';
    out += ch;
  }
  return out + "\"";
}

}  // namespace

std::vector<EmittedFunction> model_evaluator_definitions(const ModelDerivation& m, const Symbols& s) {
  return {intermediates_function(m), dispersion_function(m, s), nls_function(m, s)};
}

std::string model_evaluator_functions(const ModelDerivation& m, const Symbols& s) {
  return emit_function(intermediates_function(m)) + "\n" + emit_function(dispersion_function(m, s)) + "\n" +
         emit_function(nls_function(m, s));
}

std::string model_definition_function(const ModelDerivation& m) {
  std::ostringstream out;
  out << "// The model's description for lrchain::Model (parameters, ranges, branches, evaluators).\n"
         "inline lrchain::ModelDefinition definition() {\n"
         "  lrchain::ModelDefinition d;\n"
      << "  d.name = " << quoted(m.file.name) << ";\n"
      << "  d.description = " << quoted(m.file.description) << ";\n"
      << "  d.file_hash = " << hash_text(m.file.hash) << "ull;\n";
  for (const auto& p : m.file.parameters) {
    const auto& r = p.range;
    out << "  d.parameters.push_back({" << quoted(p.name) << ", " << quoted(r.text) << ", "
        << number_text(p.default_value.to_double()) << ", " << (r.has_lower ? "true" : "false") << ", "
        << (r.has_upper ? "true" : "false") << ", " << (r.lower_closed ? "true" : "false") << ", "
        << (r.upper_closed ? "true" : "false") << ", " << (r.has_lower ? number_text(r.lower.to_double()) : "0") << ", "
        << (r.has_upper ? number_text(r.upper.to_double()) : "0") << "});\n";
  }
  for (const auto& i : m.file.intermediates) out << "  d.intermediates.push_back(" << quoted(i.name) << ");\n";
  for (const auto& b : m.branches) out << "  d.branch_names.push_back(" << quoted(b.name) << ");\n";
  out << "  d.mean_flow = " << (m.coefficients.mean_flow ? "true" : "false") << ";\n"
      << "  d.degree = " << m.branches.size() << ";\n"
      << "  d.evaluators = {&intermediates, &dispersion, &nls};\n"
         "  return d;\n}\n";
  return out.str();
}

std::string model_header(const ModelDerivation& m, const Symbols& s) {
  std::ostringstream out;
  out << "// GENERATED FILE - DO NOT EDIT.\n"
         "// Written by lrchain-derive from models/" << m.file.name << ".toml (FNV-1a 64 " << hash_text(m.file.hash)
      << "): the double evaluators of\n"
         "// the model's dispersion relation and NLS coefficients (docs/models.md).\n"
         "// Regenerate with `cmake --build build --target regenerate`.\n"
         "#pragma once\n\n#include <cmath>\n\n#include \"lrchain/model.hpp\"\n\n"
         "namespace lrchain::generated::model_" << m.file.name << " {\n\n"
      << model_evaluator_functions(m, s) << "\n" << model_definition_function(m) << "\n"
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
