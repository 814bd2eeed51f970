#include "lrchain/numeric_parse.hpp"

#include <charconv>
#include <cmath>
#include <numbers>

#include "lrchain/errors.hpp"

namespace lrchain {
namespace {

bool parse_decimal(std::string_view s, double& out) {
  if (s.empty()) return false;
  if (s.front() == '+') s.remove_prefix(1);
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

std::string trim(std::string_view s) {
  std::string r;
  for (char ch : s)
    if (ch != ' ' && ch != '\t') r.push_back(ch);
  return r;
}

// "a" | "a*pi" | "api" | "pi" | "-pi" with a decimal.
bool parse_numerator(std::string_view s, double& out) {
  constexpr std::string_view pi = "pi";
  if (s.size() >= pi.size() && s.substr(s.size() - pi.size()) == pi) {
    std::string_view factor = s.substr(0, s.size() - pi.size());
    if (!factor.empty() && factor.back() == '*') factor.remove_suffix(1);
    double f = 1.0;
    if (factor.empty() || factor == "+") f = 1.0;
    else if (factor == "-") f = -1.0;
    else if (!parse_decimal(factor, f)) return false;
    out = f * std::numbers::pi;  // may overflow (1e308pi): parse_number refuses it
    return true;
  }
  return parse_decimal(s, out);
}

}  // namespace

double parse_number(std::string_view text, const std::string& parameter) {
  const std::string s = trim(text);
  const auto fail = [&]() -> double {
    throw InvalidParameter(parameter, "expected a number such as 0.25, 1e-3, 1/3 or 3*pi/5, got '" +
                                          std::string(text) + "'");
  };
  const auto finite = [&](double value) -> double {
    if (!std::isfinite(value))
      throw InvalidParameter(parameter, "'" + std::string(text) +
                                            "' is out of range: a number must be finite (|x| < 1.8e308)");
    return value;
  };
  const auto slash = s.find('/');
  double value = 0.0;
  if (slash == std::string::npos) {
    if (!parse_numerator(s, value)) return fail();
    return finite(value);
  }
  double num = 0.0, den = 0.0;
  if (!parse_numerator(std::string_view(s).substr(0, slash), num)) return fail();
  if (!parse_decimal(std::string_view(s).substr(slash + 1), den) || den == 0.0) return fail();
  return finite(num / den);
}

}  // namespace lrchain
