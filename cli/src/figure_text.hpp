#pragma once
// Text in the CLI's gnuplot figures. The figures use gnuplot's enhanced text mode (x_{n}, ω_{b},
// T_{b} as subscripts, as in the simulator's figures); a name from a model file or the user
// ("diatomic_chain") is shown as written.
#include <string>

namespace lrchain::cli {

// `text` for a single-quoted gnuplot string in enhanced mode, shown literally: the characters
// enhanced text interprets (_ ^ @ & ~ { }) are escaped and a quote is doubled.
inline std::string gnuplot_literal(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '_' || c == '^' || c == '@' || c == '&' || c == '~' || c == '{' || c == '}') out += '\\';
    out += c == '\'' ? std::string("''") : std::string(1, c);
  }
  return out;
}

}  // namespace lrchain::cli
