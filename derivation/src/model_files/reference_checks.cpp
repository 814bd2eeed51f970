// Checks of shipped model files against results known independently of the file: the C++
// reference models of the generated header (models.cpp), the paper's closed forms, and FPUT as
// the homogeneous chain with K2 = 1, K3 = a, K4 = b.
#include <sstream>

#include "lrchain/derivation/model_derivation.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

// The file's symbol named `name` (parameter or named intermediate); ex() when absent.
ex file_symbol(const ModelFile& f, const std::string& name) {
  for (const auto& p : f.parameters)
    if (p.name == name) return p.symbol;
  for (const auto& i : f.intermediates)
    if (i.name == name) return i.symbol;
  return ex();
}

// Every coefficient with `rename` applied (file symbols -> the reference's symbols).
DerivedCoefficients renamed(const DerivedCoefficients& d, const exmap& rename) {
  DerivedCoefficients r = d;
  for (ex* e : {&r.dispersion, &r.group_velocity, &r.gamma, &r.curvature_over_gamma, &r.beta_over_gamma,
                &r.nonresonance1, &r.h_n1_over_gamma, &r.nonresonance2, &r.lambda_n2, &r.curvature, &r.beta, &r.h,
                &r.lambda, &r.h_tilde, &r.h_tilde_numerator})
    *e = e->subs(rename, subs_options::no_pattern);
  for (auto* v : {&r.kernel, &r.left_kernel, &r.vanishing_modulo_dispersion})
    for (auto& e : *v) e = e.subs(rename, subs_options::no_pattern);
  return r;
}

// normal(a - b) = 0 for every explicit coefficient (identical rational functions).
CheckResult same_coefficients(const std::string& name, const DerivedCoefficients& a, const DerivedCoefficients& b,
                              const exmap& b_substitution = {}) {
  const std::vector<std::pair<const char*, std::pair<ex, ex>>> pairs{
      {"c", {a.group_velocity, b.group_velocity}}, {"gamma", {a.gamma, b.gamma}},
      {"omega''", {a.curvature, b.curvature}},     {"beta", {a.beta, b.beta}},
      {"h", {a.h, b.h}},                           {"lambda", {a.lambda, b.lambda}},
      {"h_tilde", {a.h_tilde, b.h_tilde}},         {"nonresonance1", {a.nonresonance1, b.nonresonance1}},
      {"nonresonance2", {a.nonresonance2, b.nonresonance2}}, {"det M", {a.dispersion, b.dispersion}}};
  for (const auto& [which, e] : pairs)
    if (!normal(e.first - e.second.subs(b_substitution, subs_options::no_pattern)).is_zero())
      return {name, false, "symbolic", std::string(which) + " differs"};
  return {name, true, "symbolic", "normal(file - reference) = 0 for c, gamma, omega'', beta, h, lambda, h_tilde, both non-resonance values, det M"};
}

exmap rename_map(const ModelFile& f, const std::vector<std::pair<std::string, ex>>& names, bool& complete) {
  exmap m;
  complete = true;
  for (const auto& [name, target] : names) {
    const ex sym = file_symbol(f, name);
    if (sym.is_zero()) complete = false;
    else m[sym] = target;
  }
  return m;
}

}  // namespace

std::vector<CheckResult> reference_checks(const ModelDerivation& m, const Symbols& s) {
  std::vector<CheckResult> out;
  const std::string& name = m.file.name;
  bool complete = false;
  if (name == "resonant_chain") {
    const exmap rename = rename_map(m.file, {{"K2", s.K2}, {"K3", s.K3}, {"K4", s.K4}, {"kappa", s.kappa}, {"rho", s.rho}}, complete);
    if (!complete) return {{"resonant_chain names K2, K3, K4, kappa, rho", false, "symbolic", "a name is missing"}};
    const LatticeDescription reference = resonant_chain_model(s), homogeneous = homogeneous_chain_model(s);
    const DerivedCoefficients ref = derive(reference, s), hom = derive(homogeneous, s);
    const DerivedCoefficients file = renamed(m.coefficients, rename);
    out.push_back(same_coefficients("resonant_chain = the reference derivation of (eq:Hertz) (generated header)", file, ref));
    for (auto& c : run_paper_checks(file, hom, s)) {
      c.name = "paper: " + c.name;
      out.push_back(std::move(c));
    }
  } else if (name == "homogeneous_chain") {
    const exmap rename = rename_map(m.file, {{"K2", s.K2}, {"K3", s.K3}, {"K4", s.K4}}, complete);
    if (!complete) return {{"homogeneous_chain names K2, K3, K4", false, "symbolic", "a name is missing"}};
    const LatticeDescription reference = homogeneous_chain_model(s);
    const DerivedCoefficients ref = derive(reference, s);
    out.push_back(same_coefficients("homogeneous_chain = the reference derivation (generated header)",
                                    renamed(m.coefficients, rename), ref));
    // Known FPU-type values (Chong13): omega^2 = K2 D1, c = K2 sin(theta)/omega, gamma = 1/omega.
    const DerivedCoefficients file = renamed(m.coefficients, rename);
    const bool known = normal(file.group_velocity - s.K2 * s.sigma / s.omega).is_zero() &&
                       normal(file.gamma - 1 / s.omega).is_zero();
    out.push_back({"homogeneous_chain: c = K2 sin(theta)/omega, gamma = 1/omega", known, "symbolic",
                   known ? "normal(derived - known) = 0" : "differs"});
  } else if (name == "fput") {
    const ex a = file_symbol(m.file, "a"), b = file_symbol(m.file, "b");
    if (a.is_zero() || b.is_zero()) return {{"fput names a, b", false, "symbolic", "a name is missing"}};
    const LatticeDescription reference = homogeneous_chain_model(s);
    const DerivedCoefficients ref = derive(reference, s);
    out.push_back(same_coefficients("fput = homogeneous_chain with K2 = 1, K3 = a, K4 = b", m.coefficients, ref,
                                    exmap{{s.K2, 1}, {s.K3, a}, {s.K4, b}}));
  }
  return out;
}

}  // namespace lrchain::derivation
