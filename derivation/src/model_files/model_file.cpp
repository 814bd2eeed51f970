#include "lrchain/derivation/model_file.hpp"

#include <fstream>
#include <regex>
#include <sstream>

#include <toml++/toml.h>

#include "lrchain/config/unicode_guard.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/one_line_text.hpp"
#include "lrchain/model.hpp"
#include "lrchain/sha256.hpp"
#include "model_expression.hpp"
#include "model_parameters.hpp"
#include "model_strings.hpp"
#include "strict_keys.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

std::string at(const std::string& file, const toml::node& node) {
  return file + ":" + std::to_string(node.source().begin.line);
}

// A TOML string value (required).
std::string text_of(const toml::table& table, const std::string& key, const std::string& file, const std::string& where) {
  const toml::node* node = table.get(key);
  if (!node) throw InputError(at(file, table) + ": " + where + " needs '" + key + "'");
  if (!node->is_string()) throw InputError(at(file, *node) + ": " + where + ": '" + key + "' must be a string");
  return std::string(*node->value<std::string>());
}

// F(r0 + x) = F(r0) + sum_k c_k x^k, k = 1..3 (the engine needs forces to cubic order).
std::vector<ex> taylor_coefficients(const ModelFunction& f, const ex& r0) {
  std::vector<ex> c;
  ex derivative = f.expression;
  ex factorial = 1;
  for (int k = 0; k <= 3; ++k) {
    if (k > 0) {
      derivative = derivative.diff(f.argument_symbol);
      factorial = factorial * k;
    }
    c.push_back(normal(derivative.subs(f.argument_symbol == r0) / factorial));
  }
  return c;
}

class Loader {
 public:
  Loader(const std::string& text, const std::string& file) : file_(file) {
    // toml++ 3.3 has undefined behaviour on some non-ASCII input (config/unicode_guard.hpp); found by
    // fuzzing this reader too.
    if (const auto bad = config::detail::find_unsafe_non_ascii(text))
      throw InputError(file + ":" + std::to_string(bad->line) + ": " + bad->what +
                       " (write it as a \\uXXXX escape inside a \"string\")");
    try {
      root_ = toml::parse(text, file);
    } catch (const toml::parse_error& e) {
      throw InputError(file + ":" + std::to_string(e.source().begin.line) + ": " + printable(e.description()));
    }
    refuse_unsafe_strings(root_, file);
    out_.path = file;
    out_.hash = fnv1a_64(text);
    out_.sha256 = sha256_hex(text);
  }

  ModelFile run() {
    reject_unknown_keys(root_, {"name", "description", "parameters", "functions", "field"}, file_, "the model file");
    out_.name = text_of(root_, "name", file_, "the model file");
    if (!std::regex_match(out_.name, std::regex("[A-Za-z][A-Za-z0-9_]*")))
      throw InputError(at(file_, *root_.get("name")) + ": name '" + out_.name + "' must be an identifier (letters, digits, _)");
    out_.description = root_.contains("description") ? text_of(root_, "description", file_, "the model file") : out_.name;
    read_parameters();
    read_functions();
    read_fields();
    return std::move(out_);
  }

 private:
  const toml::table& table_at(const std::string& key) {
    static const toml::table empty;
    const toml::node* node = root_.get(key);
    if (!node) return empty;
    if (!node->is_table()) throw InputError(at(file_, *node) + ": '" + key + "' must be a table");
    return *node->as_table();
  }

  void read_parameters() {
    for (const auto& [key, node] : table_at("parameters")) {
      ModelParameter p;
      p.name = std::string(key.str());
      p.line = int(node.source().begin.line);
      const std::string where = at(file_, node) + ": parameter " + p.name;
      if (!std::regex_match(p.name, std::regex("[A-Za-z][A-Za-z0-9]*")) || reserved(p.name))
        throw InputError(where + ": the name must be letters and digits and not one of omega, theta, c, gamma, D1, sigma, eps, E, n, I, Pi or a function name");
      if (!node.is_table()) throw InputError(where + " must be a table { default = ..., range = \"...\" }");
      const toml::table& t = *node.as_table();
      reject_unknown_keys(t, {"default", "range", "description"}, file_, "parameter " + p.name);
      const toml::node* d = t.get("default");
      if (!d) throw InputError(where + " needs 'default' (a number or a fraction such as \"4/9\")");
      if (!exact_value(*d, p.default_value)) throw InputError(at(file_, *d) + ": parameter " + p.name + ": default must be a number or a fraction such as \"4/9\"");
      p.range = t.contains("range") ? parse_range(text_of(t, "range", file_, "parameter " + p.name), at(file_, *t.get("range")) + ": parameter " + p.name)
                                    : parse_range("(-inf, inf)", where);
      if (!p.range.contains(p.default_value))
        throw InputError(at(file_, *d) + ": parameter " + p.name + ": default " + to_text(p.default_value) + " is outside its range " + p.range.text);
      if (t.contains("description")) p.description = text_of(t, "description", file_, "parameter " + p.name);
      p.symbol = realsymbol(p.name);
      out_.parameters.push_back(p);
    }
    // TOML tables are read sorted by key: keep the file's order instead.
    std::stable_sort(out_.parameters.begin(), out_.parameters.end(), [](const auto& a, const auto& b) { return a.line < b.line; });
  }

  static bool reserved(const std::string& name) {
    for (const char* r : {"omega", "theta", "c", "gamma", "D1", "sigma", "eps", "E", "n", "I", "Pi", "sqrt", "exp", "log",
                          "sin", "cos", "tan", "sinh", "cosh", "tanh", "pow"})
      if (name == r) return true;
    return false;
  }

  symtab parameter_table() const {
    symtab t;
    for (const auto& p : out_.parameters) t[p.name] = p.symbol;
    return t;
  }

  void read_functions() {
    for (const auto& [key, node] : table_at("functions")) {
      ModelFunction f;
      f.name = std::string(key.str());
      const std::string where = at(file_, node) + ": function " + f.name;
      if (!std::regex_match(f.name, std::regex("[A-Za-z][A-Za-z0-9]*")) || reserved(f.name) || parameter_table().count(f.name))
        throw InputError(where + ": the name must be letters and digits, not a parameter and not a reserved name");
      if (!node.is_table()) throw InputError(where + " must be a table { argument = \"r\", expression = \"...\" }");
      const toml::table& t = *node.as_table();
      reject_unknown_keys(t, {"argument", "expression", "taylor", "contact"}, file_, "function " + f.name);
      f.argument = text_of(t, "argument", file_, "function " + f.name);
      if (!std::regex_match(f.argument, std::regex("[A-Za-z][A-Za-z0-9]*")))
        throw InputError(where + ": argument '" + f.argument + "' must be a name such as r");
      f.argument_symbol = realsymbol(f.argument);
      ExpressionContext context;
      context.symbols = parameter_table();
      context.symbols[f.argument] = f.argument_symbol;
      context.max_terms = kMaxLawTerms;  // its Taylor coefficients multiply each other in the derivation
      std::vector<FunctionCall> calls;
      f.expression_text = text_of(t, "expression", file_, "function " + f.name);
      context.where = at(file_, *t.get("expression")) + ": function " + f.name;
      double law_terms = 1;
      f.expression = parse_model_expression(f.expression_text, context, calls, &law_terms);
      out_.divisors.push_back({context.where, "the expression of function " + f.name, f.expression, false});
      if (t.contains("contact")) {
        f.contact_text = text_of(t, "contact", file_, "function " + f.name);
        context.where = at(file_, *t.get("contact")) + ": contact of function " + f.name;
        f.contact = parse_model_expression(f.contact_text, context, calls);
      }
      if (const toml::node* names = t.get("taylor")) {
        const toml::array* a = names->as_array();
        if (!a || a->size() != 3)
          throw InputError(at(file_, *names) + ": function " + f.name + ": taylor must list three names (F'(r0), F''(r0)/2, F'''(r0)/6)");
        for (const auto& n : *a) {
          const auto s = n.value<std::string>();
          if (!s || !std::regex_match(*s, std::regex("[A-Za-z][A-Za-z0-9]*")) || reserved(*s) || context.symbols.count(*s))
            throw InputError(at(file_, *names) + ": function " + f.name + ": taylor names must be new names (letters, digits)");
          f.taylor_names.push_back(*s);
        }
      }
      // Named Taylor coefficients (K2, K3, K4) stay single symbols in the forces.
      function_terms_[f.name] = f.taylor_names.empty() ? law_terms : 1;
      out_.functions.push_back(f);
    }
  }

  // Replaces each call F(arg) by F's Taylor polynomial about arg's equilibrium value (fields zero).
  ex expand_calls(const ex& e, const std::vector<FunctionCall>& calls, const std::string& where) {
    exmap replacement;
    for (const auto& call : calls) {
      const ModelFunction& f = function(call.function);
      exmap zero;
      for (const auto& row : out_.model.shifted)
        for (const auto& s : row) zero[s] = 0;
      const ex r0 = normal(call.argument.subs(zero));
      std::vector<ex> c;
      try {
        c = taylor_coefficients(f, r0);
      } catch (const std::exception& e) {  // GiNaC: a pole or an undefined value at the equilibrium
        throw InputError(where + ": function " + f.name + " has no Taylor expansion about its equilibrium " +
                         f.argument + " = " + to_text(r0) + " (" + e.what() + ")");
      }
      out_.divisors.push_back({where, f.name + "'(" + to_text(r0) + ") of function " + f.name, c[1]});
      if (!f.taylor_names.empty())
        name_intermediates(f, f.taylor_names, r0, c, where);
      else if (has_sum_coefficient(c) && !called_elsewhere(f, r0))
        name_intermediates(f, automatic_taylor_names(f), r0, c, where);
      const ex x = call.argument - r0;
      replacement[call.placeholder] = c[0] + c[1] * x + c[2] * pow(x, 2) + c[3] * pow(x, 3);
    }
    return e.subs(replacement, subs_options::no_pattern);
  }

  const ModelFunction& function(const std::string& name) const {
    for (const auto& f : out_.functions)
      if (f.name == name) return f;
    throw std::logic_error("function " + name);
  }

  // A Taylor coefficient that is a sum in the parameters, as (1 + a + b) in (1 + a + b) r: the
  // derivation's rational arithmetic then takes GCDs of such sums at every step (a three-field chain
  // took minutes instead of a second), so the coefficients are named automatically (F_d1, ...).
  static bool has_sum_coefficient(const std::vector<ex>& c) {
    for (int k = 1; k <= 3; ++k)
      if (is_a<add>(expand(c[k]))) return true;
    return false;
  }
  // Names of F'(r0), F''(r0)/2 and F'''(r0)/6 for a law without `taylor` names: F_d1, F_d2, F_d3
  // (no name of a file has an underscore, so they are new).
  static std::vector<std::string> automatic_taylor_names(const ModelFunction& f) {
    return {f.name + "_d1", f.name + "_d2", f.name + "_d3"};
  }
  // Whether the automatic names of f already stand for its coefficients about another equilibrium.
  bool called_elsewhere(const ModelFunction& f, const ex& r0) const {
    const std::vector<std::string> names = automatic_taylor_names(f);
    const std::vector<ex> c = taylor_coefficients(f, r0);
    for (const auto& i : out_.intermediates)
      for (int k = 1; k <= 3; ++k)
        if (i.name == names[k - 1] && !normal(i.value - c[k]).is_zero()) return true;
    return false;
  }

  // Taylor coefficients of a law with named coefficients (K2, K3, K4) become those symbols.
  void name_intermediates(const ModelFunction& f, const std::vector<std::string>& names, const ex& r0,
                          std::vector<ex>& c, const std::string& where) {
    for (int k = 1; k <= 3; ++k) {
      const std::string& name = names[k - 1];
      auto it = std::find_if(out_.intermediates.begin(), out_.intermediates.end(), [&](const auto& i) { return i.name == name; });
      if (it == out_.intermediates.end()) {
        out_.intermediates.push_back({name, realsymbol(name), c[k]});
        it = out_.intermediates.end() - 1;
      } else if (!normal(it->value - c[k]).is_zero()) {
        throw InputError(where + ": function " + f.name + " is called about two different equilibria (" + to_text(r0) +
                         "), so its taylor names are ambiguous");
      }
      c[k] = it->symbol;
    }
  }

  void read_fields() {
    const toml::node* node = root_.get("field");
    if (!node) throw InputError(file_ + ":1: the model needs at least one [[field]] (name, mass, force)");
    const toml::array* fields = node->as_array();
    if (!fields || !fields->is_array_of_tables()) throw InputError(at(file_, *node) + ": 'field' must be an array of tables [[field]]");
    std::vector<const toml::table*> tables;
    for (const auto& f : *fields) {
      const toml::table& t = *f.as_table();
      reject_unknown_keys(t, {"name", "mass", "force"}, file_, "[[field]]");
      const std::string name = text_of(t, "name", file_, "[[field]]");
      bool taken = parameter_table().count(name) > 0;
      for (const auto& f : out_.functions)
        taken |= f.name == name || std::find(f.taylor_names.begin(), f.taylor_names.end(), name) != f.taylor_names.end();
      if (!std::regex_match(name, std::regex("[A-Za-z][A-Za-z0-9]*")) || reserved(name) || taken)
        throw InputError(at(file_, t) + ": field name '" + name + "' must be a new name (letters, digits)");
      for (const auto& other : out_.model.fields)
        if (other == name) throw InputError(at(file_, t) + ": field '" + name + "' is defined twice");
      out_.model.fields.push_back(name);
      tables.push_back(&t);
    }
    LatticeDescription& m = out_.model;
    m.name = out_.name;
    m.description = out_.description;
    init_shift_symbols(m);
    ExpressionContext context;
    context.symbols = parameter_table();
    context.fields = m.fields;
    for (const auto& row : m.shifted) context.shifted.emplace_back(row.begin(), row.end());
    for (const auto& f : out_.functions) context.functions.push_back(f.name);
    context.function_terms = function_terms_;
    ExpressionContext mass_context;
    mass_context.symbols = parameter_table();
    exmap zero;
    for (const auto& row : m.shifted)
      for (const auto& s : row) zero[s] = 0;
    lst shift_symbols;
    for (const auto& row : m.shifted)
      for (const auto& s : row) shift_symbols.append(s);
    for (std::size_t i = 0; i < tables.size(); ++i) {
      const toml::table& t = *tables[i];
      const std::string field = m.fields[i];
      std::vector<FunctionCall> calls;
      out_.mass_text.push_back(t.contains("mass") ? text_of(t, "mass", file_, "field " + field) : "1");
      mass_context.where = (t.contains("mass") ? at(file_, *t.get("mass")) : at(file_, t)) + ": mass of field " + field;
      const ex mass = parse_model_expression(out_.mass_text.back(), mass_context, calls);
      if (mass.is_zero()) throw InputError(mass_context.where + ": the mass must not be zero");
      out_.divisors.push_back({mass_context.where, "the mass", mass});
      out_.force_text.push_back(text_of(t, "force", file_, "field " + field));
      const std::string where = at(file_, *t.get("force")) + ": force of field " + field;
      if (out_.first_force_where.empty()) out_.first_force_where = where;
      context.where = where;
      calls.clear();
      const ex force = expand_calls(parse_model_expression(out_.force_text.back(), context, calls), calls, where);
      if (!force.is_polynomial(shift_symbols))
        throw InputError(where + ": the force must be polynomial in the shifted fields once the named functions are "
                                 "expanded; write a non-polynomial law as a [functions] entry");
      const ex at_rest = normal(force.subs(zero));
      if (!at_rest.is_zero())
        throw InputError(where + ": the force does not vanish at equilibrium (all fields zero): it is " + to_text(at_rest));
      m.inertia.push_back(mass);
      m.rhs.push_back(force);
    }
    for (const auto& p : out_.parameters) m.parameters.push_back(p.symbol);
    for (const auto& i : out_.intermediates) m.parameters.push_back(i.symbol);
  }

  std::string file_;
  toml::table root_;
  ModelFile out_;
  std::map<std::string, double> function_terms_;  // expanded terms of each law (expression_bounds.hpp)
};

}  // namespace

// Any other failure of GiNaC on the file's expressions is the file's fault too: exit 2 naming it.
// Messages (and ModelFile::path, which only names the file) show `path` with its bytes outside printable ASCII as \xNN when it has a
// control character or invalid UTF-8 (one line on stderr whatever the path).
ModelFile parse_model_text(const std::string& text, const std::string& path) {
  const std::string shown = one_line_text_problem(path).empty() ? path : printable(path);
  try {
    return Loader(text, shown).run();
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(shown + ": the model's expressions cannot be evaluated: " + e.what());
  }
}

ModelFile load_model_file(const std::filesystem::path& path) {
  return parse_model_text(read_model_file_bytes(path.string()), path.string());
}

}  // namespace lrchain::derivation
