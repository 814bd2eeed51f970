#include "expression_bounds.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <vector>

namespace lrchain::derivation {

namespace {

// What is known of a subexpression: whether it is a number, its size (log10 of an upper bound of
// numerator and denominator; parameters counted as up to 10), its value when it is a number, and
// its degree in the fields.
struct Bound {
  bool number = false;
  double digits = 0;   // log10 of the largest of |numerator|, denominator
  double value = 0;    // its value (may be inf)
  double degree = 0;   // upper bound on the degree of the polynomial it expands to
  double terms = 1;    // upper bound on its number of terms once expanded
};

struct Broken : std::runtime_error {
  using std::runtime_error::runtime_error;
};

std::string text_of(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  return buffer;
}

class Estimator {
 public:
  Estimator(const std::string& text, const std::map<std::string, double>& symbol_terms, double max_terms)
      : text_(text), symbol_terms_(symbol_terms), max_terms_(max_terms) {}

  Bound run() { return sum(); }

 private:
  void skip() {
    while (i_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[i_]))) ++i_;
  }
  bool take(char c) {
    skip();
    if (i_ < text_.size() && text_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }

  void check(const Bound& b) const {
    if (b.digits > kMaxNumberDigits)
      throw Broken("a power that reaches about 10^" + text_of(b.digits) + " (more than " + text_of(kMaxNumberDigits) +
                   " digits, parameters counted as up to 10) is too large for exact arithmetic");
    if (b.degree > kMaxPolynomialDegree)
      throw Broken("a power of degree " + text_of(b.degree) + " in the fields or arguments (more than " +
                   text_of(kMaxPolynomialDegree) + "); forces are used to cubic order");
    if (!(b.terms <= max_terms_))
      throw Broken("it expands to about " + text_of(b.terms) + " terms (more than " + text_of(max_terms_) +
                   "; a power of a sum expands to all its products) and would take minutes to derive");
  }

  Bound sum() {
    Bound b = product();
    while (true) {
      skip();
      if (i_ >= text_.size() || (text_[i_] != '+' && text_[i_] != '-')) return b;
      const bool minus = text_[i_++] == '-';
      const Bound r = product();
      b = {b.number && r.number, std::max(b.digits, r.digits) + 0.31, minus ? b.value - r.value : b.value + r.value,
           std::max(b.degree, r.degree), b.number && r.number ? 1 : b.terms + r.terms};
      check(b);
    }
  }

  Bound product() {
    Bound b = unary();
    while (true) {
      skip();
      if (i_ >= text_.size() || (text_[i_] != '*' && text_[i_] != '/')) return b;
      const bool divide = text_[i_++] == '/';
      const Bound r = unary();
      b = {b.number && r.number, b.digits + r.digits, divide ? b.value / r.value : b.value * r.value, b.degree + r.degree,
           b.terms * r.terms};
      check(b);
    }
  }

  Bound unary() {
    if (take('-')) {
      Bound b = unary();
      b.value = -b.value;
      return b;
    }
    if (take('+')) return unary();
    return power();
  }

  // a^b (right-associative as GiNaC's parser reads it).
  Bound power() {
    const Bound base = primary();
    if (!take('^')) return base;
    const Bound exponent = unary();
    return raise(base, exponent);
  }

  Bound raise(const Bound& base, const Bound& exponent) const {
    Bound b;
    if (exponent.number) {
      const double e = std::isfinite(exponent.value) ? std::abs(exponent.value) : HUGE_VAL;
      b.number = base.number;
      b.digits = base.digits * e;
      b.value = std::pow(base.value, exponent.value);
      b.degree = base.degree * e;
      // A number to a huge power, or a field to one: e itself may be the problem (x^(10^10)).
      b.terms = multinomial_terms(base.terms, std::floor(e));
      if (e > 1e6) b.digits = b.degree = b.terms = HUGE_VAL;
    } else {
      b.degree = base.degree;  // a symbolic exponent (r^alpha): never expanded
      b.digits = base.digits;
    }
    if (base.number && base.digits == 0 && std::abs(base.value) == 1) b.digits = b.degree = 0;  // 1^e, (-1)^e
    check(b);
    return b;
  }

  // Terms of (t terms)^n expanded: at most the number of monomials of degree n in t variables,
  // C(t + n - 1, n) (a sum to a fractional power keeps its integer part expanded).
  static double multinomial_terms(double t, double n) {
    if (t <= 1 || n <= 1) return t <= 1 ? 1 : t;
    return std::round(std::exp(std::lgamma(t + n) - std::lgamma(n + 1) - std::lgamma(t)));
  }

  Bound primary() {
    skip();
    if (i_ >= text_.size()) return {};
    const char c = text_[i_];
    if (c == '(') {
      ++i_;
      const Bound b = sum();
      take(')');
      return b;
    }
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      const std::size_t start = i_;
      while (i_ < text_.size() && (std::isdigit(static_cast<unsigned char>(text_[i_])) || text_[i_] == '.')) ++i_;
      const std::string digits = text_.substr(start, i_ - start);
      Bound b;
      b.number = true;
      b.digits = double(digits.size());
      b.value = std::strtod(digits.c_str(), nullptr);
      if (std::isfinite(b.value) && b.value > 0) b.digits = std::max(0.0, std::log10(b.value));
      check(b);
      return b;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = i_;
      while (i_ < text_.size() && (std::isalnum(static_cast<unsigned char>(text_[i_])) || text_[i_] == '_')) ++i_;
      const std::string name = text_.substr(start, i_ - start);
      // Fields (shift_*) have degree 1, a call of a named law (call_*) its cubic Taylor polynomial,
      // a parameter or argument degree 0 and a value counted as up to 10.
      if (!take('(')) {
        const auto known = symbol_terms_.find(name);
        const double terms = known == symbol_terms_.end() ? 1 : known->second;
        if (name.rfind("shift_", 0) == 0) return {false, 0, 0, 1, 1};
        if (name.rfind("call_", 0) == 0) return {false, 0, 0, 3, terms};
        return {false, 1, 0, 0, terms};
      }
      std::vector<Bound> arguments{sum()};
      while (take(',')) arguments.push_back(sum());
      take(')');
      return call(name, arguments);
    }
    ++i_;  // anything else is GiNaC's parser's to refuse
    return {};
  }

  Bound call(const std::string& name, const std::vector<Bound>& a) const {
    if (name == "pow" && a.size() == 2) return raise(a[0], a[1]);
    if ((name == "exp" || name == "sinh" || name == "cosh") && a[0].number &&
        !(std::abs(a[0].value) <= kMaxExponentialArgument))
      throw Broken(name + " of a number beyond " + text_of(kMaxExponentialArgument) + " overflows double precision");
    // sqrt, exp, log, trigonometric: Taylor-expanded (degree 1 before expansion), or a number.
    Bound b;
    b.number = a[0].number;
    b.digits = a[0].digits;
    b.value = 1;
    b.degree = a[0].degree > 0 ? 1 : 0;
    if (name == "sqrt") b.degree = a[0].degree / 2;
    return b;
  }

  const std::string& text_;
  const std::map<std::string, double>& symbol_terms_;
  double max_terms_;
  std::size_t i_ = 0;
};

}  // namespace

ExpressionCost expression_cost(const std::string& plain, const std::map<std::string, double>& symbol_terms,
                               double max_terms) {
  // Nesting first: the estimator below and GiNaC's parser recurse once per parenthesis.
  long depth = 0, deepest = 0;
  for (const char ch : plain) {
    depth += ch == '(' ? 1 : ch == ')' ? -1 : 0;
    deepest = std::max(deepest, depth);
  }
  if (deepest > kMaxNestingDepth)
    return {"parentheses nested " + std::to_string(deepest) + " deep (more than " + std::to_string(kMaxNestingDepth) + ")"};
  try {
    return {"", Estimator(plain, symbol_terms, max_terms).run().terms};
  } catch (const Broken& e) {
    return {e.what()};
  }
}

}  // namespace lrchain::derivation
