// Generated contact tables of the lattice kernels (contact_overlaps_text.hpp).
#include "contact_overlaps_text.hpp"

#include <algorithm>
#include <sstream>

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

struct LinearTerm {
  std::size_t variable;
  int shift;
  ex coefficient;
};

// The linear form of `e` in the kernel variables: terms (variable-major, shifts ascending) and the
// constant; false when e is not linear in them.
bool linear_form(const ex& e, const KernelVariables& x, std::vector<LinearTerm>& terms, ex& constant) {
  const ex expanded = expand(e);
  exmap zero;
  for (std::size_t g = 0; g < x.variables.size(); ++g)
    for (int k = -x.reach; k <= x.reach; ++k) zero[x.at(g, k)] = 0;
  terms.clear();
  for (std::size_t g = 0; g < x.variables.size(); ++g)
    for (int k = -x.reach; k <= x.reach; ++k) {
      if (!expanded.has(x.at(g, k))) continue;
      const ex coefficient = expanded.diff(ex_to<symbol>(x.at(g, k)));
      if (!coefficient.subs(zero, subs_options::no_pattern).is_equal(coefficient)) return false;
      terms.push_back({g, k, coefficient});
    }
  constant = expanded.subs(zero, subs_options::no_pattern);
  return true;
}

std::string text(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

// " + 2*u[n]", "-u[n+1]", " - (kappa)*v[n]": one term of a printed sum.
std::string signed_term(const ex& coefficient, const std::string& what, bool first) {
  const bool number = is_a<numeric>(coefficient);
  const bool negative = number && ex_to<numeric>(coefficient).is_negative();
  const ex size = negative ? ex(-coefficient) : coefficient;
  std::string out = first ? (negative ? "-" : "") : (negative ? " - " : " + ");
  if (what.empty()) return out + text(size);
  if (!size.is_equal(1)) out += number ? text(size) + "*" : "(" + text(size) + ")*";
  return out + what;
}

std::string c_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) out += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
  return out + "\"";
}

}  // namespace

std::string contact_call_name(const std::string& law, const ex& argument, const std::vector<std::string>& fields,
                              const KernelVariables& x) {
  std::vector<LinearTerm> terms;
  ex constant;
  int lowest = x.reach;
  for (std::size_t g = 0; g < fields.size(); ++g)
    for (int k = -x.reach; k <= x.reach; ++k)
      if (argument.has(x.at(g, k))) lowest = std::min(lowest, k);
  auto site = [&](std::size_t g, int k) {
    const int m = k - lowest;
    return fields.at(g) + (m == 0 ? "[n]" : "[n+" + std::to_string(m) + "]");
  };
  if (!linear_form(argument, x, terms, constant)) {  // printed by GiNaC with the variables renamed
    exmap named;
    for (std::size_t g = 0; g < fields.size(); ++g)
      for (int k = -x.reach; k <= x.reach; ++k) named[x.at(g, k)] = symbol(site(g, k));
    return law + "(" + text(argument.subs(named, subs_options::no_pattern)) + ")";
  }
  // Highest site first, led by a positive term where there is one: "v[n] - u[n]", "u[n+1] - u[n]".
  std::stable_sort(terms.begin(), terms.end(),
                   [](const LinearTerm& a, const LinearTerm& b) { return a.shift > b.shift; });
  const auto positive = std::find_if(terms.begin(), terms.end(), [](const LinearTerm& t) {
    return is_a<numeric>(t.coefficient) && ex_to<numeric>(t.coefficient).is_positive();
  });
  if (positive != terms.end()) std::rotate(terms.begin(), positive, positive + 1);
  std::string sum;
  for (const auto& t : terms) sum += signed_term(t.coefficient, site(t.variable, t.shift), sum.empty());
  if (!constant.is_zero() || sum.empty()) sum += signed_term(constant, "", sum.empty());
  return law + "(" + sum + ")";
}

std::string contact_overlaps_text(const std::string& form, const std::vector<ContactOverlap>& bonds,
                                  const KernelVariables& x, const std::function<std::string(const ex&)>& c_text,
                                  const std::string& parameter_locals) {
  if (bonds.empty()) return "";
  std::ostringstream names, counts, variables, shifts, values;
  std::size_t term = 0;
  for (std::size_t j = 0; j < bonds.size(); ++j) {
    std::vector<LinearTerm> terms;
    ex constant;
    const bool linear = linear_form(bonds[j].overlap, x, terms, constant);
    int lowest = x.reach;
    for (const auto& t : terms) lowest = std::min(lowest, t.shift);
    names << (j ? ", " : "") << c_string(bonds[j].name);
    counts << (j ? ", " : "") << (linear ? long(terms.size()) : -1L);
    values << "  offsets[" << j << "] = " << (linear ? c_text(constant) : std::string("0.0")) << ";\n";
    if (!linear) continue;
    for (const auto& t : terms) {
      variables << (term ? ", " : "") << t.variable;
      shifts << (term ? ", " : "") << t.shift - lowest;
      values << "  coefficients[" << term++ << "] = " << c_text(t.coefficient) << ";\n";
    }
  }
  std::ostringstream os;
  const std::string p = form + "_contact_";
  os << "// One-sided contacts of the " << form << " form: bond j's overlap at site n is offsets[j] plus\n"
     << "// coefficient times variable[n + shift] over its terms (lrchain_lattice_contacts).\n"
     << "const char* const " << p << "names[] = {" << names.str() << "};\n"
     << "const int " << p << "term_counts[] = {" << counts.str() << "};\n";
  if (term > 0)
    os << "const int " << p << "variables[] = {" << variables.str() << "};\n"
       << "const int " << p << "shifts[] = {" << shifts.str() << "};\n";
  os << "\nvoid " << p << "forms(const double* P, double* offsets, double* coefficients) {\n"
     << parameter_locals << values.str() << "}\n\n"
     << "const lrchain_lattice_contacts " << form << "_contacts = {" << bonds.size() << ", " << p << "names, " << p
     << "term_counts, " << (term > 0 ? p + "variables, " + p + "shifts, " : std::string("nullptr, nullptr, ")) << p
     << "forms};\n\n";
  return os.str();
}

}  // namespace lrchain::derivation
