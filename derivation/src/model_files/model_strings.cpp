#include "model_strings.hpp"

#include <cstdio>

#include "lrchain/errors.hpp"

namespace lrchain::derivation {

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

void check(std::string_view text, const std::string& where, const std::string& what, std::size_t max_bytes) {
  if (text.size() > max_bytes)
    throw InputError(where + ": " + what + " has " + std::to_string(text.size()) + " bytes, more than the " +
                     std::to_string(max_bytes) + " a model file allows");
  const std::string reason = unsafe_string_reason(text);
  if (!reason.empty())
    throw InputError(where + ": " + what + " has " + reason +
                     "; model-file strings are one line of printable UTF-8 text");
}

void walk(const toml::node& node, const std::string& key_path, const std::string& file);

void walk_table(const toml::table& table, const std::string& key_path, const std::string& file) {
  for (const auto& [key, value] : table) {
    const std::string name = key_path.empty() ? printable(key.str()) : key_path + "." + printable(key.str());
    const long line = key.source().begin.line ? long(key.source().begin.line) : long(value.source().begin.line);
    check(key.str(), file + ":" + std::to_string(line) + ": key " + name, "the key", kMaxModelKeyBytes);
    walk(value, name, file);
  }
}

void walk(const toml::node& node, const std::string& key_path, const std::string& file) {
  if (const toml::table* t = node.as_table()) {
    walk_table(*t, key_path, file);
  } else if (const toml::array* a = node.as_array()) {
    for (const auto& element : *a) walk(element, key_path, file);
  } else if (const auto* s = node.as_string()) {
    check(s->get(), file + ":" + std::to_string(node.source().begin.line) + ": key " + key_path, "the value",
          kMaxModelStringBytes);
  }
}

}  // namespace

std::string unsafe_string_reason(std::string_view text) {
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

std::string printable(std::string_view text) {
  constexpr std::size_t shown = 80;  // a message stays one readable line, whatever the key holds
  std::string out;
  if (text.size() > shown) return printable(text.substr(0, shown)) + "... (" + std::to_string(text.size()) + " bytes)";
  for (const char ch : text) {
    const auto b = static_cast<unsigned char>(ch);
    if (b >= 0x20 && b < 0x7f) out += ch;
    else out += "\\x" + byte_text(b).substr(2);
  }
  return out;
}

void refuse_unsafe_strings(const toml::table& root, const std::string& file) { walk_table(root, "", file); }

}  // namespace lrchain::derivation
