// Printing GiNaC expressions as C++ double arithmetic for the lattice kernels.
#include "c_printer.hpp"

#include <algorithm>
#include <cstdio>
#include <vector>
#include <sstream>
#include <string>
#include <stdexcept>

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

std::string number(const numeric& x) {
  if (x.is_integer()) {
    std::ostringstream os;
    os << x << ".0";
    return x.is_negative() ? "(" + os.str() + ")" : os.str();
  }
  if (x.is_rational()) return "(" + number(x.numer()) + "/" + number(x.denom()) + ")";
  if (!x.is_real()) throw std::invalid_argument("complex number in lattice code");
  char buffer[40];
  std::snprintf(buffer, sizeof buffer, "%.17g", x.to_double());
  return std::string("(") + buffer + ")";
}

// -sum, term by term (each term keeps its structure).
ex negated_sum(const ex& sum) {
  ex negated = 0;
  for (std::size_t j = 0; j < sum.nops(); ++j) negated += -sum.op(j);
  return negated;
}

// text^k for a positive integer k.
// Written out as products (no helper call: GCC does not inline across the kernels' target clones).
std::string integer_power_text(const std::string& text, const numeric& k) {
  if (k == 1) return text;
  if (k > 4) return "std::pow(" + text + ", " + std::to_string(k.to_long()) + ".0)";
  std::string out = "(" + text;
  for (long i = 1; i < k.to_long(); ++i) out += "*" + text;
  return out + ")";
}

// text^(k + 1/2), k >= 0.
std::string half_power_text(const std::string& text, const numeric& k) {
  const std::string root = "__builtin_sqrt(" + text + ")";
  return k.is_zero() ? root : "(" + integer_power_text(text, k) + "*" + root + ")";
}

std::string power_text(const ex& base, const ex& exponent) {
  std::string b = c_expression(base);
  if (is_a<add>(base) && exponent.info(info_flags::even)) b = std::min(b, c_expression(negated_sum(base)));
  if (is_a<numeric>(exponent)) {
    const numeric p = ex_to<numeric>(exponent);
    if (p.is_integer()) {
      if (p.is_positive()) return integer_power_text(b, p);
      return "(1.0/" + integer_power_text(b, -p) + ")";
    }
    if (p.is_rational() && p.denom() == 2) {
      const numeric k = (p.numer().is_positive() ? p.numer() - 1 : -p.numer() - 1) / 2;
      const std::string text = half_power_text(b, k);
      return p.is_positive() ? text : "(1.0/" + text + ")";
    }
  }
  return "std::pow(" + b + ", " + c_expression(exponent) + ")";
}

// The parts sorted and joined (a canonical text for a sum or product).
std::string joined(std::vector<std::string> parts, const std::string& separator) {
  std::sort(parts.begin(), parts.end());
  std::string out;
  for (std::size_t i = 0; i < parts.size(); ++i) out += (i ? separator : "") + parts[i];
  return out;
}

}  // namespace

std::string c_expression(const ex& e) {
  if (is_a<numeric>(e)) return number(ex_to<numeric>(e));
  if (is_a<symbol>(e)) return ex_to<symbol>(e).get_name();
  if (is_a<add>(e)) {
    std::vector<std::string> terms;  // sorted: the text does not depend on GiNaC's term order
    for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(c_expression(e.op(i)));
    return "(" + joined(terms, " + ") + ")";
  }
  if (is_a<mul>(e)) {
    // A sum (or an integer power of a sum) is printed as whichever of +-sum has the smaller text,
    // the sign moved to the coefficient: GiNaC's choice between (a - b) c and (b - a) (-c) depends
    // on its term order. Texts only: GiNaC would re-evaluate a rebuilt power.
    std::vector<std::string> top, bottom;
    numeric coefficient = 1;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const ex factor = e.op(i);
      if (is_a<numeric>(factor)) {
        coefficient *= ex_to<numeric>(factor);
        continue;
      }
      const bool power_of_sum = is_a<power>(factor) && is_a<add>(factor.op(0)) && is_a<numeric>(factor.op(1)) &&
                                ex_to<numeric>(factor.op(1)).is_integer();
      if (is_a<add>(factor) || power_of_sum) {
        const ex sum = power_of_sum ? factor.op(0) : factor;
        std::string text = c_expression(sum);
        const std::string negated = c_expression(negated_sum(sum));
        const numeric k = power_of_sum ? ex_to<numeric>(factor.op(1)) : numeric(1);
        if (negated < text) {
          text = negated;
          if (k.is_odd()) coefficient = -coefficient;
        }
        if (!power_of_sum) top.push_back(text);
        else if (k.is_positive()) top.push_back(integer_power_text(text, k));
        else bottom.push_back(integer_power_text(text, -k));
        continue;
      }
      if (is_a<power>(factor) && is_a<numeric>(factor.op(1)) && ex_to<numeric>(factor.op(1)).is_negative())
        bottom.push_back(c_expression(pow(factor.op(0), -factor.op(1))));
      else
        top.push_back(c_expression(factor));
    }
    if (coefficient != 1) top.push_back(number(coefficient));
    const std::string numerator = top.empty() ? "1.0" : joined(top, "*");
    const std::string denominator = joined(bottom, "*");
    return denominator.empty() ? "(" + numerator + ")" : "(" + numerator + "/(" + denominator + "))";
  }
  if (is_a<power>(e)) return power_text(e.op(0), e.op(1));
  if (is_a<function>(e)) {
    std::string name = ex_to<function>(e).get_name();
    if (name == "abs") name = "fabs";
    std::string out = "std::" + name + "(";
      for (std::size_t i = 0; i < e.nops(); ++i) out += (i ? ", " : "") + c_expression(e.op(i));
    return out + ")";
  }
  if (is_a<constant>(e)) return number(ex_to<numeric>(e.evalf()));
  throw std::invalid_argument("cannot print " + [&] {
    std::ostringstream os;
    os << e;
    return os.str();
  }() + " as C++");
}

}  // namespace lrchain::derivation
