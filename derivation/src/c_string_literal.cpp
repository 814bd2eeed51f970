#include "lrchain/derivation/c_string_literal.hpp"

namespace lrchain::derivation {

// Octal escapes stop after three digits (hex escapes do not), so a digit after one cannot join it.
std::string c_string_literal(std::string_view text) {
  std::string out = "\"";
  for (const char ch : text) {
    const auto byte = static_cast<unsigned char>(ch);
    if (byte >= 0x20 && byte <= 0x7e && byte != '"' && byte != '\\' && byte != '?') {
      out += ch;
    } else {
      out += '\\';
      out += char('0' + (byte >> 6));
      out += char('0' + ((byte >> 3) & 7));
      out += char('0' + (byte & 7));
    }
  }
  return out + "\"";
}

}  // namespace lrchain::derivation
