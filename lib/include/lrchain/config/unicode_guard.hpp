#pragma once
// Guard against a toml++ 3.3 defect (Debian's libtomlplusplus 3.3.0; upstream issues
// marzer/tomlplusplus#190 and #295, fixed upstream by pull request #305): its whitespace test
// reaches __builtin_unreachable (undefined behaviour) for most non-ASCII characters. The parser
// applies that test to characters outside strings and comments (where non-ASCII is never valid
// TOML) and to the character after a backslash in a basic string (an escape, or a line-ending
// backslash and the next line's first character). Found by fuzzing the config loader.
#include <optional>
#include <string>
#include <string_view>

namespace lrchain::config::detail {

struct UnsafeCharacter {
  long line;
  std::string what;  // why the file is refused, for the message
};

// The first non-ASCII byte where toml++ 3.3 would test it for whitespace, if any (a UTF-8 byte
// order mark at the very start is allowed).
std::optional<UnsafeCharacter> find_unsafe_non_ascii(std::string_view text);

}  // namespace lrchain::config::detail
