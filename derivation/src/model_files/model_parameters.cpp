#include "model_parameters.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <regex>
#include <sstream>

#include "lrchain/errors.hpp"
#include "model_expression.hpp"
#include "strict_keys.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

bool exact_value(const toml::node& node, numeric& value) {
  if (auto i = node.value_exact<int64_t>()) {
    value = numeric(long(*i));
    return true;
  }
  if (auto d = node.value_exact<double>()) {
    char buffer[64];
    const auto r = std::to_chars(buffer, buffer + sizeof buffer, *d);
    return parse_exact_number(std::string(buffer, r.ptr), value);
  }
  if (auto s = node.value_exact<std::string>()) return parse_exact_number(*s, value);
  return false;
}

ParameterRange parse_range(const std::string& text, const std::string& where) {
  static const std::regex pattern(R"(\s*([\[(])\s*([^,]+?)\s*,\s*([^\])]+?)\s*([\])])\s*)");
  std::smatch m;
  if (!std::regex_match(text, m, pattern)) throw InputError(where + ": range '" + text + "' must look like \"(0, inf)\" or \"[1, 4]\"");
  ParameterRange r;
  r.text = text;
  r.lower_closed = m[1] == "[";
  r.upper_closed = m[4] == "]";
  const std::string lo = m[2], hi = m[3];
  if (lo != "-inf") {
    if (!parse_exact_number(lo, r.lower)) throw InputError(where + ": bad lower bound '" + lo + "' in range '" + text + "'");
    r.has_lower = true;
  }
  if (hi != "inf" && hi != "+inf") {
    if (!parse_exact_number(hi, r.upper)) throw InputError(where + ": bad upper bound '" + hi + "' in range '" + text + "'");
    r.has_upper = true;
  }
  return r;
}

bool ParameterRange::contains(const numeric& v) const {
  if (has_lower && (lower_closed ? v < lower : v <= lower)) return false;
  if (has_upper && (upper_closed ? v > upper : v >= upper)) return false;
  return true;
}

exmap parameter_values(const ModelFile& model, const std::vector<std::pair<std::string, std::string>>& overrides) {
  exmap values;
  for (const auto& p : model.parameters) values[p.symbol] = p.default_value;
  for (const auto& [name, text] : overrides) {
    const std::string_view wanted = name;  // a lambda may not capture a structured binding (clang 14)
    auto it = std::find_if(model.parameters.begin(), model.parameters.end(), [&](const auto& p) { return p.name == wanted; });
    if (it == model.parameters.end()) {
      std::vector<std::string> names;
      for (const auto& p : model.parameters) names.push_back(p.name);
      const std::string guess = closest_name(name, names);
      throw InputError("--set " + name + ": model " + model.name + " has no parameter '" + name + "'" +
                       (guess.empty() ? "" : " (did you mean '" + guess + "'?)"));
    }
    numeric v;
    if (!parse_exact_number(text, v)) throw InvalidParameter(name, "'" + text + "' is not a number (at most 2000 digits, exponent within +-2000) or a fraction such as 4/9");
    if (!it->range.contains(v)) throw InvalidParameter(name, to_text(v) + " is outside its range " + it->range.text);
    values[it->symbol] = v;
  }
  for (const auto& i : model.intermediates) values[i.symbol] = i.value.subs(values, subs_options::no_pattern);
  return values;
}

std::string hash_text(std::uint64_t hash) {
  char buffer[19];
  std::snprintf(buffer, sizeof buffer, "0x%016llx", static_cast<unsigned long long>(hash));
  return buffer;
}

}  // namespace lrchain::derivation
