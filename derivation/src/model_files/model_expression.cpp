#include "model_expression.hpp"

#include "expression_bounds.hpp"

#include <cctype>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "lrchain/errors.hpp"
#include "strict_keys.hpp"

namespace lrchain::derivation {

using namespace GiNaC;

namespace {

const std::vector<std::string> kBuiltinFunctions{"sqrt", "exp", "log", "sin", "cos", "tan", "sinh", "cosh", "tanh", "pow"};

bool identifier_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identifier_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

class Translator {
 public:
  Translator(const ExpressionContext& context, std::vector<FunctionCall>& calls) : context_(context), calls_(calls) {
    table_ = context.symbols;
    for (std::size_t f = 0; f < context.fields.size(); ++f) {
      for (int m = -3; m <= 3; ++m) table_[shift_name(f, m)] = context.shifted[f][m + 3];
      table_[context.fields[f]] = context.shifted[f][3];  // a bare field name means field[n]
    }
  }

  // Rewrites text into plain GiNaC syntax (placeholders for shifts and calls), checking every name.
  std::string translate(const std::string& text) {
    std::string out;
    std::size_t i = 0;
    while (i < text.size()) {
      const char c = text[i];
      if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
        const std::size_t start = i;
        while (i < text.size() && (std::isdigit(static_cast<unsigned char>(text[i])) || text[i] == '.')) ++i;
        if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
          std::size_t j = i + 1;
          if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
          if (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) {
            i = j;
            while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
          }
        }
        numeric exact_value;  // decimals become exact fractions (no inexact numbers in the derivation)
        const std::string number = text.substr(start, i - start);
        if (!parse_exact_number(number, exact_value)) {
          const std::string shown = number.size() > 24 ? number.substr(0, 20) + "... (" + std::to_string(number.size()) + " characters)" : number;
          fail("bad number '" + shown + "' (a number has at most " + std::to_string(long(kMaxNumberDigits)) +
               " digits and an exponent within +-" + std::to_string(long(kMaxNumberDigits)) + ")");
        }
        std::ostringstream os;
        os << "(" << exact_value << ")";
        out += os.str();
        continue;
      }
      if (!identifier_start(c)) {
        out += c;
        ++i;
        continue;
      }
      const std::size_t start = i;
      while (i < text.size() && identifier_char(text[i])) ++i;
      const std::string name = text.substr(start, i - start);
      std::size_t next = i;
      while (next < text.size() && std::isspace(static_cast<unsigned char>(text[next]))) ++next;
      if (next < text.size() && text[next] == '[') {
        const std::size_t close = text.find(']', next);
        if (close == std::string::npos) fail("missing ']' after '" + name + "['");
        out += shifted_field(name, text.substr(next + 1, close - next - 1));
        i = close + 1;
      } else if (next < text.size() && text[next] == '(') {
        if (std::find(context_.functions.begin(), context_.functions.end(), name) != context_.functions.end()) {
          const std::size_t close = matching_parenthesis(text, next);
          out += function_call(name, text.substr(next + 1, close - next - 1));
          i = close + 1;
        } else if (std::find(kBuiltinFunctions.begin(), kBuiltinFunctions.end(), name) != kBuiltinFunctions.end()) {
          out += name;
        } else {
          std::vector<std::string> known = context_.functions;
          known.insert(known.end(), kBuiltinFunctions.begin(), kBuiltinFunctions.end());
          fail("undefined function '" + name + "'" + suggestion(name, known));
        }
      } else {
        if (!table_.count(name) || name.find('_') != std::string::npos) fail("undefined symbol '" + name + "'" + suggestion(name, visible_names()));
        out += name;
      }
    }
    return out;
  }

  [[noreturn]] void fail(const std::string& problem) const { throw InputError(context_.where + ": " + problem); }

  const symtab& table() const { return table_; }

 private:
  std::string shift_name(std::size_t f, int m) const {
    // Internal names contain '_', which model names never do.
    return "shift_" + context_.fields[f] + (m < 0 ? "_m" : "_p") + std::to_string(m < 0 ? -m : m);
  }

  std::vector<std::string> visible_names() const {
    std::vector<std::string> names;
    for (const auto& [name, value] : table_)
      if (name.find('_') == std::string::npos) names.push_back(name);
    return names;
  }

  static std::string suggestion(const std::string& name, const std::vector<std::string>& known) {
    const std::string guess = closest_name(name, known);
    return guess.empty() ? "" : " (did you mean '" + guess + "'?)";
  }

  // u[n], u[n+2], u[n - 1]: the symbol for field u at site n+m.
  std::string shifted_field(const std::string& name, const std::string& index) {
    const auto it = std::find(context_.fields.begin(), context_.fields.end(), name);
    if (it == context_.fields.end())
      fail("unknown field '" + name + "[" + index + "]'" +
           (context_.fields.empty() ? " (fields are not allowed here)" : suggestion(name, context_.fields)));
    static const std::regex pattern(R"(\s*n\s*(?:([+-])\s*([0-9]+))?\s*)");
    std::smatch match;
    if (!std::regex_match(index, match, pattern)) fail("index of '" + name + "[" + index + "]' must be n, n+m or n-m");
    int m = 0;
    if (match[1].matched) {
      if (match[2].str().size() > 3) fail("shift beyond +-3 in '" + name + "[" + index + "]'");
      m = std::stoi(match[2].str()) * (match[1].str() == "-" ? -1 : 1);
    }
    if (m < -3 || m > 3) fail("shift beyond +-3 in '" + name + "[" + index + "]' (the lattice couples at most 3 sites away)");
    return shift_name(std::size_t(it - context_.fields.begin()), m);
  }

  std::size_t matching_parenthesis(const std::string& text, std::size_t open) const {
    int depth = 0;
    for (std::size_t j = open; j < text.size(); ++j) {
      if (text[j] == '(') ++depth;
      if (text[j] == ')' && --depth == 0) return j;
    }
    fail("unbalanced parentheses");
  }

  // F(arg): the argument parsed on its own, the call replaced by a placeholder symbol. For the
  // bounds it stands for the terms of F's Taylor coefficients (its law's), which every product with
  // the call multiplies; the argument, a polynomial of degree <= 12 in the fields, is bounded alone.
  std::string function_call(const std::string& name, const std::string& argument_text) {
    const ex argument = parse(translate(argument_text));
    const std::string placeholder = "call_" + std::to_string(calls_.size());
    const auto law = context_.function_terms.find(name);
    placeholder_terms_[placeholder] = law == context_.function_terms.end() ? 1 : law->second;
    calls_.push_back({name, argument, realsymbol(placeholder)});
    table_[placeholder] = calls_.back().placeholder;
    return placeholder;
  }

 public:
  ex parse(const std::string& plain, double* expanded_terms = nullptr) const {
    const ExpressionCost cost = expression_cost(plain, placeholder_terms_, context_.max_terms);
    if (!cost.problem.empty()) fail(cost.problem);
    if (expanded_terms) *expanded_terms = cost.expanded_terms;
    try {
      parser reader(table_, /*strict=*/true);
      return reader(plain);
    } catch (const std::exception& e) {
      const std::string message = e.what();
      fail("cannot parse the expression: " + message.substr(0, message.find('\n')));
    }
  }

 private:
  const ExpressionContext& context_;
  std::vector<FunctionCall>& calls_;
  symtab table_;
  std::map<std::string, double> placeholder_terms_;  // call_N -> terms of the Taylor polynomial it stands for
};

}  // namespace

ex parse_model_expression(const std::string& text, const ExpressionContext& context, std::vector<FunctionCall>& calls,
                          double* expanded_terms) {
  Translator t(context, calls);
  return t.parse(t.translate(text), expanded_terms);
}

std::string to_text(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

bool parse_exact_number(const std::string& text, numeric& value) {
  static const std::regex pattern(R"(\s*([+-]?)([0-9]*)(?:\.([0-9]*))?(?:[eE]([+-]?[0-9]+))?(?:\s*/\s*([0-9]+))?\s*)");
  std::smatch m;
  if (!std::regex_match(text, m, pattern) || (m[2].length() == 0 && m[3].length() == 0)) return false;
  // Up to kMaxNumberDigits digits and |exponent| (expression_bounds.hpp; docs/models.md).
  if (m[2].length() + m[3].length() > kMaxNumberDigits || (m[5].matched && m[5].length() > kMaxNumberDigits)) return false;
  if (m[4].matched && (m[4].length() > 6 || std::abs(std::stol(m[4].str())) > kMaxNumberDigits)) return false;
  const std::string digits = m[2].str() + m[3].str();
  numeric mantissa = 0;
  for (char c : digits) mantissa = mantissa * 10 + (c - '0');
  const long exponent = (m[4].matched ? std::stol(m[4].str()) : 0) - long(m[3].length());
  value = mantissa * numeric(10).power(numeric(exponent));
  if (m[5].matched) {
    numeric denominator = 0;
    for (char c : m[5].str()) denominator = denominator * 10 + (c - '0');
    if (denominator.is_zero()) return false;
    value = value / denominator;
  }
  if (m[1].str() == "-") value = -value;
  return true;
}

}  // namespace lrchain::derivation
