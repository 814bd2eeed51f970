#include "lrchain/derivation/emit_cpp.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

// A canonical text of an expression that does not depend on GiNaC's internal term order (which
// follows hash values that change from run to run): children of sums and products sorted.
class CanonicalText {
 public:
  const std::string& of(const ex& e) {
    if (auto it = memo_.find(e); it != memo_.end()) return it->second;
    std::string text;
    if (is_a<numeric>(e)) {
      std::ostringstream os;
      os << e;
      text = os.str();
    } else if (is_a<symbol>(e)) {
      text = ex_to<symbol>(e).get_name();
    } else if (is_a<GiNaC::add>(e) || is_a<mul>(e)) {
      std::vector<std::string> parts;
      for (const auto& child : e) parts.push_back(of(child));
      std::sort(parts.begin(), parts.end());
      const char* sep = is_a<GiNaC::add>(e) ? "+" : "*";
      text = "(";
      for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? sep : "") + parts[i];
      text += ")";
    } else if (is_a<power>(e)) {
      text = of(e.op(0)) + "^" + of(e.op(1));
    } else {
      std::ostringstream os;
      os << e;
      text = os.str();
    }
    return memo_.emplace(e, text).first->second;
  }

 private:
  std::map<ex, std::string, ex_is_less> memo_;
};

// Children of a sum or product in canonical order.
std::vector<ex> sorted_children(const ex& e, CanonicalText& canon) {
  std::vector<ex> children(e.begin(), e.end());
  std::sort(children.begin(), children.end(),
            [&](const ex& a, const ex& b) { return canon.of(a) < canon.of(b); });
  return children;
}

// Fixes the sign of each polynomial factor (P or -P, whichever has the smaller canonical text),
// so that factor()'s hash-dependent choice of leading term does not leak into the output.
ex canonical_signs(const ex& product, CanonicalText& canon) {
  std::vector<ex> factors = is_a<mul>(product) ? std::vector<ex>(product.begin(), product.end()) : std::vector<ex>{product};
  ex result = 1;
  for (const ex& f : factors) {
    ex base = f, exponent = 1;
    if (is_a<power>(f)) {
      base = f.op(0);
      exponent = f.op(1);
    }
    if (is_a<GiNaC::add>(base) && exponent.info(info_flags::integer)) {
      base = expand(base);  // a sum of monomials has one structure whatever the term order
      const numeric content = base.integer_content();  // and one scale: primitive integer coefficients
      base = expand(base / content);
      result *= pow(content, exponent);
      const ex negated = expand(-base);
      if (canon.of(negated) < canon.of(base)) {
        result *= pow(-1, exponent);
        base = negated;
      }
    }
    result *= pow(base, exponent);
  }
  return result;
}

}  // namespace

ex factored(const ex& e) {
  CanonicalText canon;
  const ex nd = normal(e).numer_denom();
  return canonical_signs(factor(nd.op(0)), canon) / canonical_signs(factor(nd.op(1)), canon);
}

namespace {

class Printer {
 public:
  Printer(const std::map<ex, std::string, ex_is_less>& names) : names_(names) {}
  CanonicalText canon;

  void count(const ex& e) {
    if (names_.count(e) || is_a<numeric>(e) || is_a<symbol>(e)) return;
    if (++uses_[e] > 1) return;  // children already counted
    for (const auto& child : e) count(child);
    if (is_a<power>(e)) count(e.op(0));
  }

  std::string print(const ex& e) {
    if (auto it = names_.find(e); it != names_.end()) return it->second;
    if (is_a<numeric>(e)) return number(ex_to<numeric>(e));
    if (auto it = temps_.find(e); it != temps_.end()) return it->second;
    std::string text = print_node(e);
    if (uses_[e] > 1 && !is_a<numeric>(e)) {
      const std::string name = "t" + std::to_string(temps_.size());
      body_ << "  const double " << name << " = " << text << ";\n";
      temps_[e] = name;
      return name;
    }
    return text;
  }

  std::string body() const { return body_.str(); }

 private:
  static std::string number(const numeric& n) {
    if (!n.is_rational()) throw std::runtime_error("non-rational number in emitted expression");
    std::ostringstream os;
    if (n.is_integer()) {
      os << n << ".0";
    } else {
      os << "(" << n.numer() << ".0 / " << n.denom() << ".0)";
    }
    std::string s = os.str();
    return n.is_negative() ? "(" + s + ")" : s;
  }

  std::string power_text(const ex& base, int n) {
    const std::string b = print(base);
    const bool atomic = is_a<symbol>(base) || temps_.count(base) || names_.count(base);
    const std::string bb = atomic ? b : "(" + b + ")";
    std::string s = bb;
    for (int i = 1; i < n; ++i) s += " * " + bb;
    return n > 1 ? "(" + s + ")" : s;
  }

  std::string print_node(const ex& e) {
    if (is_a<GiNaC::add>(e)) {
      std::string s;
      const std::vector<ex> terms = sorted_children(e, canon);
      for (std::size_t i = 0; i < terms.size(); ++i) {
        const std::string term = print(terms[i]);
        if (i == 0) s = term;
        else if (!term.empty() && term[0] == '-') s += " - " + term.substr(1);
        else s += " + " + term;
      }
      return "(" + s + ")";
    }
    if (is_a<mul>(e)) {
      std::vector<std::string> num, den;
      numeric coeff = 1;
      for (const auto& f : sorted_children(e, canon)) {
        if (is_a<numeric>(f)) { coeff *= ex_to<numeric>(f); continue; }
        if (is_a<power>(f) && f.op(1).info(info_flags::negint)) {
          const int n = -ex_to<numeric>(f.op(1)).to_int();
          den.push_back(n == 1 ? wrap(f.op(0)) : power_text(f.op(0), n));
        } else {
          num.push_back(wrap(f));
        }
      }
      std::string s;
      const bool negative = coeff.is_negative();
      if (negative) coeff = -coeff;
      if (coeff != 1 || num.empty()) num.insert(num.begin(), number(coeff));
      for (std::size_t i = 0; i < num.size(); ++i) s += (i ? " * " : "") + num[i];
      if (!den.empty()) {
        std::string d;
        for (std::size_t i = 0; i < den.size(); ++i) d += (i ? " * " : "") + den[i];
        s += " / (" + d + ")";
      }
      return negative ? "-(" + s + ")" : s;
    }
    if (is_a<power>(e)) {
      if (!e.op(1).info(info_flags::integer)) throw std::runtime_error("non-integer exponent in emitted expression");
      const int n = ex_to<numeric>(e.op(1)).to_int();
      if (n > 0) return power_text(e.op(0), n);
      return "(1.0 / " + power_text(e.op(0), -n) + ")";
    }
    if (is_a<symbol>(e)) throw std::runtime_error("unmapped symbol " + ex_to<symbol>(e).get_name());
    throw std::runtime_error("unsupported expression node in emission");
  }

  std::string wrap(const ex& e) {
    const std::string s = print(e);
    if (is_a<GiNaC::add>(e) && !temps_.count(e)) return s;  // add prints its own parentheses
    return s;
  }

  const std::map<ex, std::string, ex_is_less>& names_;
  std::map<ex, int, ex_is_less> uses_;
  std::map<ex, std::string, ex_is_less> temps_;
  std::ostringstream body_;
};

}  // namespace

std::string emit_function(const EmittedFunction& f) {
  std::map<ex, std::string, ex_is_less> names;
  for (const auto& [sym, name] : f.inputs) names[sym] = name;
  for (const auto& [name, sym] : f.output_symbols) names[sym] = "r." + name;
  std::vector<ex> forms;
  for (const auto& [name, e] : f.outputs) forms.push_back(factored(e));
  Printer printer(names);
  for (const ex& e : forms) printer.count(e);
  std::ostringstream out;
  out << "// " << f.comment << "\n";
  out << "inline " << f.result_type << " " << f.name << "(";
  for (std::size_t i = 0; i < f.inputs.size(); ++i) out << (i ? ", " : "") << "double " << f.inputs[i].second;
  out << ") noexcept {\n  " << f.result_type << " r{};\n";
  std::ostringstream assignments;
  std::string collected;
  for (std::size_t i = 0; i < forms.size(); ++i) {
    const std::string rhs = printer.print(forms[i]);
    // Temporaries needed by this output were appended to the body; flush them before the assignment.
    const std::string body = printer.body();
    out << body.substr(collected.size());
    collected = body;
    out << "  r." << f.outputs[i].first << " = " << rhs << ";\n";
  }
  out << "  return r;\n}\n";
  return out.str();
}

}  // namespace lrchain::derivation
