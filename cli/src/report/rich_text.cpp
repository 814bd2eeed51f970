// ASCII physics names and LaTeX labels -> HTML (rich_text.hpp).
#include "rich_text.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <vector>

#include "latex_numbering.hpp"
#include "markdown_html.hpp"

namespace lrchain::report {

namespace {

const std::map<std::string, std::string>& greek() {
  static const std::map<std::string, std::string> letters = {
      {"alpha", "α"}, {"beta", "β"},   {"gamma", "γ"}, {"delta", "δ"},  {"epsilon", "ε"},
      {"theta", "θ"}, {"kappa", "κ"},  {"lambda", "λ"}, {"rho", "ρ"},   {"omega", "ω"},
      {"pi", "π"},    {"chi", "χ"},    {"tau", "τ"},   {"xi", "ξ"}};
  return letters;
}

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// A name without subscript: a Greek letter ("rho"), a Greek letter with digits ("delta0" -> δ₀ as
// a subscript), or the name itself.
std::string symbol(const std::string& name) {
  if (const auto g = greek().find(name); g != greek().end()) return g->second;
  std::size_t digits = name.size();
  while (digits > 0 && std::isdigit(static_cast<unsigned char>(name[digits - 1]))) --digits;
  if (digits < name.size() && digits > 0)
    if (const auto g = greek().find(name.substr(0, digits)); g != greek().end())
      return g->second + "<sub>" + name.substr(digits) + "</sub>";
  return html_escape(name);
}

bool is_symbol_base(const std::string& name) {
  return name.size() <= 2 || greek().count(name) > 0;
}

// The paper label "fig:focus3" / "eq:disp1d" starting at `i`, if the paper numbers it: the label,
// its citation as printed ("Fig. 7", "eq. (7)", with `space` between word and number), and `end` past it.
struct Citation {
  std::string label, shown;
  std::size_t end = 0;
};

std::optional<Citation> citation(const std::string& text, std::size_t i, const std::string& space) {
  const bool figure = text.compare(i, 4, "fig:") == 0, equation = text.compare(i, 3, "eq:") == 0;
  if (!figure && !equation) return std::nullopt;
  std::size_t q = i + (figure ? 4 : 3);
  while (q < text.size() && (is_word_char(text[q]) || (text[q] == ':' && q + 1 < text.size() && is_word_char(text[q + 1])))) ++q;
  Citation c{text.substr(i, q - i), "", q};
  const auto number = paper_number(c.label);
  if (!number) return std::nullopt;
  c.shown = number->kind == PaperNumber::Kind::figure ? "Fig." + space + std::to_string(number->number)
                                                      : "eq." + space + "(" + std::to_string(number->number) + ")";
  return c;
}

}  // namespace

std::string rich_text(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    const bool word_start = i == 0 || !is_word_char(text[i - 1]);
    if (word_start && std::isalpha(static_cast<unsigned char>(text[i]))) {
      if (const auto cite = citation(text, i, "&nbsp;")) {
        out += "<span class=\"cite\" title=\"" + html_escape(cite->label) + "\">" + cite->shown + "</span>";
        i = cite->end;
        continue;
      }
      std::size_t q = i;
      while (q < text.size() && is_word_char(text[q])) ++q;
      std::string word = text.substr(i, q - i);
      // c_+ / omega_- : a '+' or '-' subscript after a trailing underscore.
      std::string sign;
      if (word.size() > 1 && word.back() == '_' && q < text.size() && (text[q] == '+' || text[q] == '-')) {
        sign = text[q] == '+' ? "+" : "&minus;";
        word.pop_back();
        ++q;
      }
      const auto underscore = word.find('_');
      if (!sign.empty() && is_symbol_base(word)) {
        out += symbol(word) + "<sub>" + sign + "</sub>";
      } else if (word == "h_tilde") {
        out += "h&#771;";
      } else if (underscore != std::string::npos && word.find('_', underscore + 1) == std::string::npos &&
                 is_symbol_base(word.substr(0, underscore)) && word.size() - underscore - 1 <= 4 &&
                 underscore + 1 < word.size()) {
        out += symbol(word.substr(0, underscore)) + "<sub>" + symbol(word.substr(underscore + 1)) + "</sub>";
      } else {
        out += sign.empty() ? symbol(word) : html_escape(word) + (sign == "+" ? "+" : "-");
      }
      i = q;
      // Primes after a symbol: omega'' -> ω″, omega_-' -> ω₋′.
      if (text.compare(i, 2, "''") == 0 && i + 2 <= text.size()) {
        out += "&Prime;";
        i += 2;
      } else if (i < text.size() && text[i] == '\'' && (i + 1 >= text.size() || !std::isalpha(static_cast<unsigned char>(text[i + 1])))) {
        out += "&prime;";
        i += 1;
      }
      continue;
    }
    if (text.compare(i, 2, "||") == 0) {  // a norm: ||x||_inf -> ‖x‖∞
      out += "&#8214;";
      i += 2;
      if (text.compare(i, 4, "_inf") == 0) {
        out += "<sub>&infin;</sub>";
        i += 4;
      }
      continue;
    }
    out += html_escape(std::string(1, text[i]));
    ++i;
  }
  return out;
}

namespace {

bool is_ascii_alnum(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'); }
bool is_ascii_alpha(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

// Start of the subscript base that ends just before text[underscore], or npos if there is none: one or
// two ASCII letters, or one Greek letter (UTF-8 lead byte 0xCE or 0xCF), not preceded by a letter,
// digit or underscore.
std::size_t subscript_base(const std::string& text, std::size_t underscore) {
  std::size_t start = underscore;
  while (start > 0 && is_ascii_alnum(text[start - 1])) --start;
  const std::size_t length = underscore - start;
  if (length == 0 && underscore >= 2) {
    const auto lead = static_cast<unsigned char>(text[underscore - 2]);
    if (lead == 0xCE || lead == 0xCF) start = underscore - 2;
  } else if (length > 2 || !is_ascii_alpha(text[start])) {
    return std::string::npos;
  }
  if (start == underscore) return std::string::npos;
  if (start > 0 && (is_ascii_alnum(text[start - 1]) || text[start - 1] == '_')) return std::string::npos;
  return start;
}

// A run of HTML-escaped text between tags, with its subscripts rendered.
std::string text_subscripts(const std::string& text) {
  std::string out;
  std::size_t copied = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '_' || subscript_base(text, i) == std::string::npos) continue;
    std::size_t end = i + 1;
    while (end < text.size() && is_ascii_alnum(text[end])) ++end;
    const bool word = end > i + 1 && end - i - 1 <= 4 && (end == text.size() || text[end] != '_');
    if (!word) continue;
    out.append(text, copied, i - copied);
    out += "<sub>" + text.substr(i + 1, end - i - 1) + "</sub>";
    copied = end;
    i = end - 1;
  }
  return out + text.substr(copied);
}

}  // namespace

std::string html_subscripts(const std::string& html) {
  std::string out;
  int verbatim = 0;  // inside <code> or <pre>
  for (std::size_t i = 0; i < html.size();) {
    if (html[i] == '<') {
      const std::size_t close = html.find('>', i);
      const std::string tag = html.substr(i, close == std::string::npos ? std::string::npos : close - i + 1);
      if (tag.rfind("<code", 0) == 0 || tag.rfind("<pre", 0) == 0) ++verbatim;
      if ((tag.rfind("</code", 0) == 0 || tag.rfind("</pre", 0) == 0) && verbatim > 0) --verbatim;
      out += tag;
      i += tag.size();
      continue;
    }
    const std::size_t next = std::min(html.find('<', i), html.size());
    const std::string text = html.substr(i, next - i);
    out += verbatim > 0 ? text : text_subscripts(text);
    i = next;
  }
  return out;
}

std::string plain_citations(const std::string& text) {
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    if (i == 0 || !is_word_char(text[i - 1]))
      if (const auto cite = citation(text, i, " ")) {
        out += cite->shown;
        i = cite->end;
        continue;
      }
    out += text[i++];
  }
  return out;
}

}  // namespace lrchain::report
