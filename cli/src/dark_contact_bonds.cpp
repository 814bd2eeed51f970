// One-sided contacts of a model file as linear overlaps of the lattice variables (dark_contact_bonds.hpp).
#include "dark_contact_bonds.hpp"

#include <ginac/ginac.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <regex>
#include <utility>
#include <vector>

#include "lrchain/derivation/model_file.hpp"
#include "lrchain/errors.hpp"

namespace lrchain::cli {

namespace {

using Terms = std::map<std::pair<int, int>, double>;  // (variable, shift) -> coefficient

// The argument texts of every call `name(...)` in a force expression (balanced parentheses).
std::vector<std::string> call_arguments(const std::string& force, const std::string& name) {
  std::vector<std::string> out;
  const std::regex call("(^|[^A-Za-z0-9_])" + name + "\\s*\\(");
  for (auto it = std::sregex_iterator(force.begin(), force.end(), call); it != std::sregex_iterator(); ++it) {
    std::size_t i = std::size_t(it->position(0) + it->length(0));
    const std::size_t start = i;
    int depth = 1;
    for (; i < force.size() && depth > 0; ++i) depth += force[i] == '(' ? 1 : (force[i] == ')' ? -1 : 0);
    if (depth == 0) out.push_back(force.substr(start, i - 1 - start));
  }
  return out;
}

// Parses an argument such as "u[n+1] - u[n]" into a GiNaC expression in shifted-field symbols.
GiNaC::ex parse_argument(const std::string& text, const derivation::ModelFile& file,
                         std::map<std::string, std::pair<int, int>>& shifted, GiNaC::symtab& table) {
  const std::regex site("([A-Za-z][A-Za-z0-9]*)\\s*\\[\\s*n\\s*(?:([+-])\\s*([0-9]+))?\\s*\\]");
  std::string rewritten;
  auto last = text.cbegin();
  for (auto it = std::sregex_iterator(text.begin(), text.end(), site); it != std::sregex_iterator(); ++it) {
    const auto& m = *it;
    const auto field = std::find(file.model.fields.begin(), file.model.fields.end(), m[1].str());
    if (field == file.model.fields.end())
      throw InputError(file.path + ": contact argument '" + text + "': '" + m[1].str() + "' is not a field");
    const int shift = m[3].matched ? (m[2].str() == "-" ? -1 : 1) * std::stoi(m[3].str()) : 0;
    const std::string symbol = "shifted_" + m[1].str() + "_" + std::to_string(shift + 100);
    shifted[symbol] = {int(field - file.model.fields.begin()), shift};
    if (!table.count(symbol)) table[symbol] = GiNaC::realsymbol(symbol);
    rewritten.append(last, m[0].first).append(symbol);
    last = m[0].second;
  }
  rewritten.append(last, text.cend());
  GiNaC::parser reader(table, true);
  return reader(rewritten);
}

double number(const GiNaC::ex& e, const std::string& where) {
  const GiNaC::ex v = e.evalf();
  if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
    throw InputError(where + ": locating contact changes needs an argument linear in the fields with numeric coefficients");
  return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

// Displacement terms sum c u_f[n+m] in strain variables: u_f = u_0 + w_f (f >= 1),
// u_0[n+m] - u_0[n] = sum_{j=1..m} r[n+j] (m > 0), -sum_{j=m+1..0} r[n+j] (m < 0).
Terms to_strain(const Terms& displacement, const std::string& where) {
  Terms strain;
  std::map<int, double> u0;
  double total = 0;
  for (const auto& [key, c] : displacement) {
    const auto [f, m] = key;
    if (f > 0) strain[{f, m}] += c;
    u0[m] += c;
    total += c;
  }
  double scale = 0;
  for (const auto& [m, c] : u0) scale = std::max(scale, std::abs(c));
  if (std::abs(total) > 1e-12 * scale)
    throw InputError(where + ": the contact argument is not translation invariant, so it has no strain form");
  for (const auto& [m, c] : u0) {
    for (int j = 1; j <= m; ++j) strain[{0, j}] += c;
    for (int j = m + 1; j <= 0; ++j) strain[{0, j}] -= c;
  }
  return strain;
}

}  // namespace

sim::dark::ContactBonds model_contact_bonds(const std::string& path, const Model& model, bool strain_form) {
  const derivation::ModelFile file = derivation::load_model_file(path);
  GiNaC::exmap values;
  GiNaC::symtab table;
  for (const auto& p : file.parameters) {
    values[p.symbol] = GiNaC::numeric(model.parameter(p.name));
    table[p.name] = p.symbol;
  }
  sim::dark::ContactBonds bonds;
  for (const auto& law : file.functions) {
    if (law.contact.is_zero()) continue;
    const std::string where = file.path + ": function " + law.name;
    const GiNaC::ex contact = GiNaC::expand(law.contact.subs(values));
    const double slope = number(contact.diff(law.argument_symbol), where);
    const double offset = number(contact.subs(law.argument_symbol == 0), where);
    for (const auto& force : file.force_text)
      for (const auto& text : call_arguments(force, law.name)) {
        std::map<std::string, std::pair<int, int>> shifted;
        const GiNaC::ex argument = GiNaC::expand(parse_argument(text, file, shifted, table).subs(values));
        Terms displacement;
        GiNaC::exmap zero;
        for (const auto& [name, key] : shifted) zero[table[name]] = 0;
        for (const auto& [name, key] : shifted) {
          const GiNaC::ex d = argument.diff(GiNaC::ex_to<GiNaC::symbol>(table[name]));
          if (!d.subs(zero).is_equal(d))
            throw InputError(where + ": locating contact changes needs an argument linear in the fields, got '" + text + "'");
          displacement[key] += slope * number(d, where);
        }
        Terms terms = strain_form ? to_strain(displacement, where) : displacement;
        int lowest = 1 << 20;
        for (const auto& [key, c] : terms)
          if (c != 0.0) lowest = std::min(lowest, key.second);
        sim::dark::ContactBond bond{law.name + "(" + text + ")", offset + slope * number(argument.subs(zero), where), {}};
        for (const auto& [key, c] : terms)
          if (c != 0.0) bond.terms.push_back({key.first, key.second - lowest, c});
        const bool known = std::any_of(bonds.begin(), bonds.end(), [&](const sim::dark::ContactBond& b) {
          if (b.offset != bond.offset || b.terms.size() != bond.terms.size()) return false;
          for (std::size_t k = 0; k < b.terms.size(); ++k)
            if (b.terms[k].variable != bond.terms[k].variable || b.terms[k].shift != bond.terms[k].shift ||
                b.terms[k].coefficient != bond.terms[k].coefficient)
              return false;
          return true;
        });
        if (!known && !bond.terms.empty()) bonds.push_back(std::move(bond));
      }
  }
  return bonds;
}

}  // namespace lrchain::cli
