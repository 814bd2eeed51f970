#include "model_strings.hpp"

#include <cstdio>

#include "lrchain/errors.hpp"
#include "lrchain/one_line_text.hpp"

namespace lrchain::derivation {

namespace {

std::string byte_text(unsigned char byte) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "0x%02x", byte);
  return buffer;
}

void check(std::string_view text, const std::string& where, const std::string& what, std::size_t max_bytes) {
  if (text.size() > max_bytes)
    throw InputError(where + ": " + what + " has " + std::to_string(text.size()) + " bytes, more than the " +
                     std::to_string(max_bytes) + " a model file allows");
  const std::string reason = one_line_text_problem(text);
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
