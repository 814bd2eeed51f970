#pragma once
// Every string of a model file (keys included) is one line of text: no control characters (C0,
// DEL, so no newline, carriage return or NUL) and valid UTF-8 (docs/models.md).
#include <string>
#include <string_view>

#include <toml++/toml.h>

namespace lrchain::derivation {

// Longest key (an identifier: parameter, function, field names) and longest string value (an
// expression, a description) of a model file. Checked before any pattern or parser reads them:
// std::regex and the expression parsers recurse once per character, so a 50000-character name
// overflowed the stack.
inline constexpr std::size_t kMaxModelKeyBytes = 64;
inline constexpr std::size_t kMaxModelStringBytes = 4096;

// Throws InputError "FILE:LINE: key K: ..." at the first key or string value of `root` (at any
// depth, arrays included) that is too long, has a control character (C0, DEL, C1, U+2028/9) or is
// not valid UTF-8.
void refuse_unsafe_strings(const toml::table& root, const std::string& file);

// `text` for a one-line message: printable ASCII as is, every other byte as \xNN.
std::string printable(std::string_view text);

}  // namespace lrchain::derivation
