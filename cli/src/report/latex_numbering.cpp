// Equation and figure numbers of a LaTeX source as the compiled document shows them
// (latex_numbering.hpp).
#include "latex_numbering.hpp"

#include <cctype>
#include <set>
#include <vector>

namespace lrchain::report {

namespace {

// The source without % comments (an escaped \% stays).
std::string without_comments(const std::string& tex) {
  std::string out;
  out.reserve(tex.size());
  for (std::size_t i = 0; i < tex.size(); ++i) {
    if (tex[i] == '\\' && i + 1 < tex.size()) {
      out += tex[i];
      out += tex[++i];
      continue;
    }
    if (tex[i] == '%') {
      while (i < tex.size() && tex[i] != '\n') ++i;
      if (i < tex.size()) out += '\n';
      continue;
    }
    out += tex[i];
  }
  return out;
}

// The contents of the brace group opening at `open` (tex[open] == '{'); `end` is set past it.
std::string brace_group(const std::string& tex, std::size_t open, std::size_t& end) {
  int depth = 0;
  for (std::size_t i = open; i < tex.size(); ++i) {
    if (tex[i] == '\\') { ++i; continue; }
    if (tex[i] == '{') ++depth;
    if (tex[i] == '}' && --depth == 0) {
      end = i + 1;
      return tex.substr(open + 1, i - open - 1);
    }
  }
  end = tex.size();
  return tex.substr(open + 1);
}

// Expands the argument-free \def macros whose body opens or closes an environment.
std::string with_environment_macros_expanded(const std::string& tex) {
  std::map<std::string, std::string> macros;
  for (std::size_t p = 0; (p = tex.find("\\def\\", p)) != std::string::npos;) {
    std::size_t q = p + 5;
    while (q < tex.size() && std::isalpha(static_cast<unsigned char>(tex[q]))) ++q;
    const std::string name = tex.substr(p + 5, q - p - 5);
    p = q;
    if (q >= tex.size() || tex[q] != '{') continue;
    std::size_t end;
    const std::string body = brace_group(tex, q, end);
    if (body.find("\\begin{") != std::string::npos || body.find("\\end{") != std::string::npos) macros[name] = body;
  }
  if (macros.empty()) return tex;
  std::string out;
  out.reserve(tex.size());
  for (std::size_t i = 0; i < tex.size();) {
    if (tex[i] == '\\' && i + 1 < tex.size() && std::isalpha(static_cast<unsigned char>(tex[i + 1]))) {
      std::size_t q = i + 1;
      while (q < tex.size() && std::isalpha(static_cast<unsigned char>(tex[q]))) ++q;
      const std::string name = tex.substr(i + 1, q - i - 1);
      if (name == "def" && q + 1 < tex.size() && tex[q] == '\\') {  // a definition itself is not content
        std::size_t r = q + 1;
        while (r < tex.size() && std::isalpha(static_cast<unsigned char>(tex[r]))) ++r;
        if (r < tex.size() && tex[r] == '{') {
          std::size_t end;
          brace_group(tex, r, end);
          i = end;
          continue;
        }
      }
      const auto m = macros.find(name);
      out += m != macros.end() ? m->second : tex.substr(i, q - i);
      i = q;
      continue;
    }
    out += tex[i++];
  }
  return out;
}

bool starts_with_at(const std::string& s, std::size_t i, const char* what) { return s.compare(i, std::char_traits<char>::length(what), what) == 0; }

const std::set<std::string> single_equations = {"equation"};
const std::set<std::string> row_equations = {"eqnarray", "align", "gather", "flalign", "alignat"};

}  // namespace

std::map<std::string, PaperNumber> number_labels(const std::string& latex) {
  const std::string tex = with_environment_macros_expanded(without_comments(latex));
  std::map<std::string, PaperNumber> labels;
  int equation = 0, figure = 0;
  std::vector<std::string> environments;
  // The innermost numbered display: its kind, the counter before it, its numbered rows so far,
  // and whether the current row is numbered and has content.
  enum class Display { none, single, rows } display = Display::none;
  int display_env_depth = 0, base = 0, numbered_rows = 0;
  bool row_numbered = true, row_has_content = false;
  int figure_env_depth = 0;
  auto end_row = [&] {
    if (row_numbered && row_has_content) ++numbered_rows;
    row_numbered = true;
    row_has_content = false;
  };
  for (std::size_t i = 0; i < tex.size();) {
    if (tex[i] != '\\') {
      if (display == Display::rows && !std::isspace(static_cast<unsigned char>(tex[i]))) row_has_content = true;
      ++i;
      continue;
    }
    if (starts_with_at(tex, i, "\\begin{") || starts_with_at(tex, i, "\\end{")) {
      const bool begin = tex[i + 1] == 'b';
      std::size_t end;
      const std::string name = brace_group(tex, tex.find('{', i), end);
      i = end;
      if (begin) {
        environments.push_back(name);
        if (display == Display::none && single_equations.count(name)) {
          display = Display::single, display_env_depth = static_cast<int>(environments.size());
          base = ++equation;
        } else if (display == Display::none && row_equations.count(name)) {
          display = Display::rows, display_env_depth = static_cast<int>(environments.size());
          base = equation, numbered_rows = 0, row_numbered = true, row_has_content = false;
        } else if (name == "figure" || name == "figure*") {
          ++figure;
          figure_env_depth = static_cast<int>(environments.size());
        }
      } else {
        if (display != Display::none && static_cast<int>(environments.size()) == display_env_depth) {
          if (display == Display::rows) {
            end_row();
            equation = base + numbered_rows;
          }
          display = Display::none;
        }
        if (static_cast<int>(environments.size()) == figure_env_depth) figure_env_depth = 0;
        if (!environments.empty()) environments.pop_back();
      }
      continue;
    }
    if (starts_with_at(tex, i, "\\label{")) {
      std::size_t end;
      const std::string label = brace_group(tex, i + 6, end);
      i = end;
      if (display == Display::single) labels[label] = {PaperNumber::Kind::equation, base};
      else if (display == Display::rows) labels[label] = {PaperNumber::Kind::equation, base + numbered_rows + 1};
      else if (figure_env_depth > 0) labels[label] = {PaperNumber::Kind::figure, figure};
      continue;
    }
    if (display == Display::rows && static_cast<int>(environments.size()) == display_env_depth) {
      if (starts_with_at(tex, i, "\\\\")) {
        end_row();
        i += 2;
        continue;
      }
      if (starts_with_at(tex, i, "\\nonumber") || starts_with_at(tex, i, "\\notag")) row_numbered = false;
    }
    if (display == Display::rows) row_has_content = true;
    ++i;  // a control word (\alpha) or a control symbol (\\, \{)
    if (i < tex.size() && !std::isalpha(static_cast<unsigned char>(tex[i]))) ++i;
    else while (i < tex.size() && std::isalpha(static_cast<unsigned char>(tex[i]))) ++i;
  }
  return labels;
}

std::optional<PaperNumber> paper_number(const std::string& label) {
  const auto& table = paper_numbers();
  for (const std::string& key : {label, label.substr(label.find(':') == std::string::npos ? 0 : label.find(':') + 1)}) {
    const auto it = table.find(key);
    if (it != table.end()) return it->second;
  }
  return std::nullopt;
}

}  // namespace lrchain::report
