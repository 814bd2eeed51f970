// User text as single-quoted gnuplot strings (gnuplot_text.hpp).
#include "lrchain/jobs/gnuplot_text.hpp"

namespace lrchain::jobs {

std::string gnuplot_text(std::string_view text, GnuplotTextMode mode) {
  static constexpr std::string_view replacement = "\xEF\xBF\xBD";  // U+FFFD in UTF-8
  static constexpr std::string_view apostrophe = "\xE2\x80\x99";   // U+2019 in UTF-8
  static constexpr std::string_view enhanced_specials = "\\_^@&~{}";
  std::string out;
  out.reserve(text.size() + 8);
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (byte < 0x20 || byte == 0x7F)
      out += replacement;
    else if (c == '\'')
      out += apostrophe;
    else if (mode == GnuplotTextMode::enhanced && enhanced_specials.find(c) != std::string_view::npos)
      out += {'\\', c};
    else
      out += c;
  }
  return out;
}

std::string gnuplot_string(std::string_view text) { return "'" + gnuplot_text(text) + "'"; }

std::string gnuplot_file_name(std::string_view name) {
  if (!name.empty() && name.front() == '/') return gnuplot_string(name);
  return gnuplot_string("./" + std::string(name));
}

}  // namespace lrchain::jobs
