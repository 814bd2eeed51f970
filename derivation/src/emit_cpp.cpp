#include "lrchain/derivation/emit_cpp.hpp"
#include "lrchain/derivation/derivation_stop.hpp"

#include <algorithm>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

// The emitter's own expression tree. GiNaC orders the operands of sums and products by hash
// values that depend on the memory layout of the running binary, and its products re-normalise
// the sign of a sum factor by whichever term happens to come first. Converting once into this
// tree, where every sum and product keeps its operands sorted by their printed text and the
// numeric coefficient of a product is kept apart, makes the emitted C++ depend only on the
// mathematical expression.
struct Node;
using NodePtr = std::shared_ptr<const Node>;

struct Node {
  enum Kind { number, symbol, sum, product, power, call } kind = number;
  numeric value = 0;               // number; coefficient of a product
  std::string name;                // symbol: the C++ name; call: the C++ function (std::pow, std::abs, ...)
  std::vector<NodePtr> children;   // sum terms / product factors (sorted by key); power: {base}; call: arguments
  int exponent = 0;                // power
  std::string key;                 // canonical text, a total order on subexpressions
  std::size_t size = 1;            // number of nodes
};

std::string number_key(const numeric& n) {
  std::ostringstream os;
  os << n;
  return os.str();
}

NodePtr make_number(const numeric& n) {
  auto node = std::make_shared<Node>();
  node->kind = Node::number;
  node->value = n;
  node->key = number_key(n);
  return node;
}

NodePtr make_symbol(const std::string& name) {
  auto node = std::make_shared<Node>();
  node->kind = Node::symbol;
  node->name = name;
  node->key = name;
  return node;
}

// A sum or product with operands sorted by key; a product's numeric factors go into its coefficient.
NodePtr make_nary(Node::Kind kind, std::vector<NodePtr> children, numeric coefficient = 1) {
  std::vector<NodePtr> flat;
  for (auto& c : children) {
    if (kind == Node::product && c->kind == Node::number) coefficient *= c->value;
    else if (kind == Node::product && c->kind == Node::product) {
      coefficient *= c->value;
      flat.insert(flat.end(), c->children.begin(), c->children.end());
    } else flat.push_back(c);
  }
  std::sort(flat.begin(), flat.end(), [](const NodePtr& a, const NodePtr& b) { return a->key < b->key; });
  if (kind == Node::product && coefficient.is_equal(1) && flat.size() == 1) return flat.front();
  if (kind == Node::product && (coefficient.is_zero() || flat.empty())) return make_number(flat.empty() ? coefficient : 0);
  auto node = std::make_shared<Node>();
  node->kind = kind;
  node->value = coefficient;
  node->children = std::move(flat);
  node->key = kind == Node::sum ? "(" : number_key(coefficient) + "*(";
  for (std::size_t i = 0; i < node->children.size(); ++i) {
    node->key += (i ? (kind == Node::sum ? "+" : "*") : "") + node->children[i]->key;
    node->size += node->children[i]->size;
  }
  node->key += ")";
  return node;
}

NodePtr make_power(const NodePtr& base, int exponent) {
  if (exponent == 1) return base;
  auto node = std::make_shared<Node>();
  node->kind = Node::power;
  node->children = {base};
  node->exponent = exponent;
  node->key = "(" + base->key + ")^" + std::to_string(exponent);
  node->size = base->size + 1;
  return node;
}

// A call of a C++ function (non-integer powers, exp, log, abs, ...); arguments keep their order.
NodePtr make_call(const std::string& function_name, std::vector<NodePtr> arguments) {
  auto node = std::make_shared<Node>();
  node->kind = Node::call;
  node->name = function_name;
  node->key = function_name + "(";
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    node->key += (i ? "," : "") + arguments[i]->key;
    node->size += arguments[i]->size;
  }
  node->key += ")";
  node->children = std::move(arguments);
  return node;
}

using Names = std::map<ex, std::string, ex_is_less>;

// GiNaC expression -> canonical tree (symbols renamed through `names`, or their own names).
NodePtr convert(const ex& e, const Names* names) {
  if (names) {
    if (auto it = names->find(e); it != names->end()) return make_symbol(it->second);
  }
  if (is_a<numeric>(e)) {
    if (!ex_to<numeric>(e).is_rational()) throw std::runtime_error("non-rational number in emitted expression");
    return make_number(ex_to<numeric>(e));
  }
  if (is_a<symbol>(e)) {
    if (names) throw std::runtime_error("unmapped symbol " + ex_to<symbol>(e).get_name());
    return make_symbol(ex_to<symbol>(e).get_name());
  }
  if (is_a<GiNaC::add>(e) || is_a<mul>(e)) {
    std::vector<NodePtr> children;
    for (const auto& child : e) children.push_back(convert(child, names));
    return make_nary(is_a<GiNaC::add>(e) ? Node::sum : Node::product, std::move(children));
  }
  if (is_a<GiNaC::power>(e)) {
    if (e.op(1).info(info_flags::integer)) return make_power(convert(e.op(0), names), ex_to<numeric>(e.op(1)).to_int());
    return make_call("std::pow", {convert(e.op(0), names), convert(e.op(1), names)});
  }
  if (is_a<function>(e)) {
    std::vector<NodePtr> arguments;
    for (const auto& argument : e) arguments.push_back(convert(argument, names));
    return make_call("std::" + ex_to<function>(e).get_name(), std::move(arguments));
  }
  throw std::runtime_error("unsupported expression node in emission");
}

// Adds the factors of factor()'s result (raised to `sign` = +1 numerator, -1 denominator). Each
// polynomial factor is expanded, made primitive (integer content into `coefficient`) and given the
// sign whose canonical text is smaller, so GiNaC's choice of leading term does not leak out.
void collect_factors(const ex& f, int sign, numeric& coefficient, std::vector<NodePtr>& factors, const Names* names) {
  if (is_a<mul>(f)) {
    for (const auto& x : f) collect_factors(x, sign, coefficient, factors, names);
    return;
  }
  if (is_a<numeric>(f)) {
    coefficient *= sign > 0 ? ex_to<numeric>(f) : ex_to<numeric>(f).inverse();
    return;
  }
  ex base = f;
  int exponent = 1;
  if (is_a<GiNaC::power>(f) && f.op(1).info(info_flags::integer)) {
    base = f.op(0);
    exponent = ex_to<numeric>(f.op(1)).to_int();
  }
  exponent *= sign;
  if (is_a<GiNaC::add>(base)) {
    ex polynomial = expand(base);
    const numeric content = polynomial.integer_content();
    polynomial = expand(polynomial / content);
    coefficient *= content.power(exponent);
    NodePtr plus = convert(polynomial, names), minus = convert(expand(-polynomial), names);
    if (minus->key < plus->key) {
      plus = minus;
      if (exponent % 2) coefficient = -coefficient;
    }
    factors.push_back(make_power(plus, exponent));
  } else {
    factors.push_back(make_power(convert(base, names), exponent));
  }
}

// Polynomials with more terms than this are emitted expanded (integer content and sign still taken
// out) instead of through GiNaC's multivariate factor(), whose time grows steeply with the size:
// on the mass-in-mass-in-mass chain of tests/derivation/mim3.toml a 27-term denominator took 0.17 s,
// a 111-term numerator 1.9 s and a 274-term one 162 s (wall, machine at load 7). The largest polynomial
// of the shipped models has 54 terms, so their emitted text does not change. The emitted evaluators'
// arithmetic is chosen from the cancellation of the expanded polynomials (evaluator_cancellation) and
// checked at 50 digits either way.
constexpr std::size_t kLargestFactoredTerms = 64;

// factor(p), or p itself when it has more than kLargestFactoredTerms terms.
ex factored_if_small(const ex& p) {
  const ex expanded = expand(p);
  if (is_a<GiNaC::add>(expanded) && expanded.nops() > kLargestFactoredTerms) return expanded;
  return factor(p);
}

// factor(numerator) / factor(denominator) as a canonical tree.
NodePtr factored_tree(const ex& e, const Names* names) {
  const ex nd = normal(e).numer_denom();
  numeric coefficient = 1;
  std::vector<NodePtr> factors;
  collect_factors(factored_if_small(nd.op(0)), 1, coefficient, factors, names);
  collect_factors(factored_if_small(nd.op(1)), -1, coefficient, factors, names);
  return make_nary(Node::product, std::move(factors), coefficient);
}

// C++ text of canonical trees; subexpressions used more than once become `const double tN`.
class Printer {
 public:
  // Temporaries and fractions in `real_type` ("double", or the alias `real` of an extended type).
  explicit Printer(std::string real_type) : real_type_(std::move(real_type)) {}

  void count(const NodePtr& e) {
    if (e->kind == Node::number || e->kind == Node::symbol) return;
    if (++uses_[e->key] > 1) return;  // children already counted
    for (const auto& child : e->children) count(child);
  }

  std::string print(const NodePtr& e) {
    if (e->kind == Node::symbol) return e->name;
    if (e->kind == Node::number) return number(e->value);
    if (auto it = temps_.find(e->key); it != temps_.end()) return it->second;
    std::string text = print_node(*e);
    if (uses_[e->key] > 1) {
      const std::string name = "t" + std::to_string(temps_.size());
      body_ << "  const " << real_type_ << " " << name << " = " << text << ";\n";
      temps_[e->key] = name;
      return name;
    }
    return text;
  }

  std::string body() const { return body_.str(); }

 private:
  // Integers exactly; a fraction divided in the function's arithmetic type (1/3 is not a double).
  std::string number(const numeric& n) const {
    std::ostringstream os;
    if (n.is_integer()) os << n << ".0";
    else if (real_type_ == "double") os << "(" << n.numer() << ".0 / " << n.denom() << ".0)";
    else os << "(real(" << n.numer() << ".0) / " << n.denom() << ".0)";
    std::string s = os.str();
    return n.is_negative() ? "(" + s + ")" : s;
  }

  std::string power_text(const NodePtr& base, int n) {
    const std::string b = print(base);
    const bool atomic = base->kind == Node::symbol || temps_.count(base->key);
    const std::string bb = atomic ? b : "(" + b + ")";
    std::string s = bb;
    for (int i = 1; i < n; ++i) s += " * " + bb;
    return n > 1 ? "(" + s + ")" : s;
  }

  std::string print_node(const Node& e) {
    if (e.kind == Node::sum) {
      std::string s;
      for (std::size_t i = 0; i < e.children.size(); ++i) {
        const std::string term = print(e.children[i]);
        if (i == 0) s = term;
        else if (!term.empty() && term[0] == '-') s += " - " + term.substr(1);
        else s += " + " + term;
      }
      return "(" + s + ")";
    }
    if (e.kind == Node::product) {
      std::vector<std::string> num, den;
      for (const auto& f : e.children) {
        if (f->kind == Node::power && f->exponent < 0) {
          const int n = -f->exponent;
          den.push_back(n == 1 ? print(f->children[0]) : power_text(f->children[0], n));
        } else {
          num.push_back(print(f));
        }
      }
      numeric coefficient = e.value;
      const bool negative = coefficient.is_negative();
      if (negative) coefficient = -coefficient;
      if (!coefficient.is_equal(1) || num.empty()) num.insert(num.begin(), number(coefficient));
      std::string s;
      for (std::size_t i = 0; i < num.size(); ++i) s += (i ? " * " : "") + num[i];
      if (!den.empty()) {
        std::string d;
        for (std::size_t i = 0; i < den.size(); ++i) d += (i ? " * " : "") + den[i];
        s += " / (" + d + ")";
      }
      return negative ? "-(" + s + ")" : s;
    }
    if (e.kind == Node::call) {
      std::string s = e.name + "(";
      for (std::size_t i = 0; i < e.children.size(); ++i) s += (i ? ", " : "") + print(e.children[i]);
      return s + ")";
    }
    // power
    if (e.exponent > 0) return power_text(e.children[0], e.exponent);
    return "(1.0 / " + power_text(e.children[0], -e.exponent) + ")";
  }

  std::string real_type_;
  std::map<std::string, int> uses_;
  std::map<std::string, std::string> temps_;
  std::ostringstream body_;
};

// Sum of the absolute values of the terms of e's expanded numerator over |denominator|: the size
// of the terms that cancel in e (a scale for deciding that e vanishes in double precision).
NodePtr term_scale_tree(const ex& e, const Names* names, const std::string& abs_function) {
  const ex nd = normal(e).numer_denom();
  ex numerator = expand(nd.op(0));
  // The sign collect_factors gives a polynomial (the magnitudes do not depend on it), so that the
  // terms are the ones printed in a factored output and become shared temporaries.
  if (is_a<GiNaC::add>(numerator) && convert(expand(-numerator), names)->key < convert(numerator, names)->key)
    numerator = expand(-numerator);
  std::vector<NodePtr> terms;
  if (is_a<GiNaC::add>(numerator)) {
    for (const auto& t : numerator) terms.push_back(make_call(abs_function, {convert(t, names)}));
  } else {
    terms.push_back(make_call(abs_function, {convert(numerator, names)}));
  }
  NodePtr sum = terms.size() == 1 ? terms.front() : make_nary(Node::sum, std::move(terms));
  if (nd.op(1).is_equal(1)) return sum;
  return make_nary(Node::product, {sum, make_power(make_call(abs_function, {factored_tree(nd.op(1), names)}), -1)});
}

}  // namespace

std::size_t emitted_size(const ex& e) { return factored_tree(e, nullptr)->size; }

std::string emit_function(const EmittedFunction& f) {
  poll_derivation_stop();  // a run-time compile stops between emitted functions
  // Struct result: outputs are fields r.NAME. Without a result type the outputs are written to the
  // lvalues named (e.g. out[3]) by a void function.
  const bool returns_struct = !f.result_type.empty();
  const auto lvalue = [&](const std::string& name) {
    if (returns_struct) return "r." + name;
    if (!f.local_outputs.empty() && name.rfind("out[", 0) == 0) return f.local_outputs + name.substr(3);
    return name;
  };
  Names names;
  for (const auto& [sym, name] : f.inputs) names[sym] = name;
  for (const auto& [name, sym] : f.output_symbols) names[sym] = lvalue(name);
  std::vector<NodePtr> forms;
  for (const auto& [name, e] : f.outputs)
    forms.push_back(f.term_scales.count(name) ? term_scale_tree(e, &names, f.abs_function)
                    : f.unfactored.count(name) ? convert(expand(e), &names)
                                               : factored_tree(e, &names));
  Printer printer(f.real_type == "double" ? "double" : "real");
  for (const auto& e : forms) printer.count(e);
  std::ostringstream out;
  out << "// " << f.comment << "\n";
  out << "inline " << (returns_struct ? f.result_type : "void") << " " << f.name << "(";
  if (!f.parameter_list.empty()) out << f.parameter_list;
  else
    for (std::size_t i = 0; i < f.inputs.size(); ++i) out << (i ? ", " : "") << "double " << f.inputs[i].second;
  out << ") noexcept {\n";
  if (returns_struct) out << "  " << f.result_type << " r{};\n";
  out << f.prologue;
  std::string collected;
  for (std::size_t i = 0; i < forms.size(); ++i) {
    const std::string rhs = printer.print(forms[i]);
    // Temporaries needed by this output were appended to the body; flush them before the assignment.
    const std::string body = printer.body();
    out << body.substr(collected.size());
    collected = body;
    out << "  " << lvalue(f.outputs[i].first) << " = " << rhs << ";\n";
  }
  out << f.epilogue;
  if (returns_struct) out << "  return r;\n";
  out << "}\n";
  return out.str();
}

}  // namespace lrchain::derivation
