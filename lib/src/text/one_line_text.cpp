#include "lrchain/one_line_text.hpp"

#include <cstdio>

namespace lrchain {

namespace {

std::string byte_text(unsigned char byte) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "0x%02x", byte);
  return buffer;
}

// Length of the UTF-8 sequence starting at text[i] (RFC 3629: no overlongs, no surrogates, at most
// U+10FFFF), or 0 when it is not one.
std::size_t utf8_sequence_length(std::string_view text, std::size_t i) {
  const auto at = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b = at(i);
  std::size_t length;
  unsigned char low = 0x80, high = 0xbf;  // the allowed range of the second byte
  if (b < 0x80) return 1;
  else if (b >= 0xc2 && b <= 0xdf) length = 2;
  else if (b >= 0xe0 && b <= 0xef) {
    length = 3;
    if (b == 0xe0) low = 0xa0;
    if (b == 0xed) high = 0x9f;
  } else if (b >= 0xf0 && b <= 0xf4) {
    length = 4;
    if (b == 0xf0) low = 0x90;
    if (b == 0xf4) high = 0x8f;
  } else {
    return 0;
  }
  if (i + length > text.size()) return 0;
  if (at(i + 1) < low || at(i + 1) > high) return 0;
  for (std::size_t k = 2; k < length; ++k)
    if (at(i + k) < 0x80 || at(i + k) > 0xbf) return 0;
  return length;
}

}  // namespace

std::string one_line_text_problem(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b < 0x20 || b == 0x7f) return "a control character (byte " + byte_text(b) + ")";
    const std::size_t length = utf8_sequence_length(text, i);
    if (length == 0) return "a byte that is not valid UTF-8 (" + byte_text(b) + ")";
    // C1 controls U+0080..U+009F (C2 80..C2 9F) and the line and paragraph separators U+2028/U+2029
    // (E2 80 A8/A9): line breaks or terminal controls to some readers.
    const auto next = [&](std::size_t k) { return static_cast<unsigned char>(text[i + k]); };
    if (length == 2 && b == 0xc2 && next(1) <= 0x9f)
      return "a control character (U+00" + byte_text(next(1)).substr(2) + ")";
    if (length == 3 && b == 0xe2 && next(1) == 0x80 && (next(2) == 0xa8 || next(2) == 0xa9))
      return std::string("a line or paragraph separator (U+202") + (next(2) == 0xa8 ? "8" : "9") + ")";
    i += length;
  }
  return {};
}

}  // namespace lrchain
