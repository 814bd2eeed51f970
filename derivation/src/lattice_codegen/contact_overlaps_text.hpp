#pragma once
// The one-sided contacts of a lattice form as generated C++ (struct lrchain_lattice_contacts of
// lib/include/lrchain/compiled_model_abi.h): each contact bond's overlap
// s_n = offset + sum_k coefficient_k q[variable_k][n + shift_k] in the form's variables, the same
// `contact(argument)` whose sign the generated accelerations clamp.
#include <ginac/ginac.h>

#include <functional>
#include <string>
#include <vector>

namespace lrchain::derivation {

// One contact bond of a form: its name and its overlap contact(argument) in kernel variables.
struct ContactOverlap {
  std::string name;   // the law and its argument in the fields, e.g. "F(u[n+1] - u[n])"
  GiNaC::ex overlap;  // in kernel variables x_g[i+k] (variables[g][k + reach]) and the parameters
};

// Kernel variables x_g[i+k] as variables[g][k + reach], |k| <= reach.
struct KernelVariables {
  const std::vector<std::vector<GiNaC::ex>>& variables;
  int reach;
  const GiNaC::ex& at(std::size_t g, int k) const { return variables.at(g).at(std::size_t(k + reach)); }
};

// C++ text defining `<form>_contacts` (a lrchain_lattice_contacts) and the function evaluating its
// linear forms at the parameters; empty when `bonds` is. An overlap that is not linear in the
// variables is emitted with term count -1 (it has no linear form). `c_text` prints an expression in
// the parameters' C names, `parameter_locals` declares them from P.
std::string contact_overlaps_text(const std::string& form, const std::vector<ContactOverlap>& bonds,
                                  const KernelVariables& variables,
                                  const std::function<std::string(const GiNaC::ex&)>& c_text,
                                  const std::string& parameter_locals);

// "F(u[n+1] - u[n])": a call of `law` whose argument is given in displacement kernel variables
// (x_f[i+k] printed as field f at n+k), shifted so that its lowest site is n.
std::string contact_call_name(const std::string& law, const GiNaC::ex& argument, const std::vector<std::string>& fields,
                              const KernelVariables& variables);

}  // namespace lrchain::derivation
