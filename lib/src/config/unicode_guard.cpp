// Finding the non-ASCII characters toml++ 3.3 cannot parse safely (unicode_guard.hpp): a small
// TOML tokenizer that follows comments and the four kinds of strings. Non-ASCII text is allowed
// only in comments and in the string value of a plain `key = "..."` line outside arrays and inline
// tables: there toml++ is certainly inside a string or comment. Anywhere else a quote may belong to
// a malformed value that toml++ scans character by character, so non-ASCII there is refused.
#include "lrchain/config/unicode_guard.hpp"

namespace lrchain::config::detail {

namespace {

bool non_ascii(char c) { return static_cast<unsigned char>(c) >= 0x80; }
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool bare_key_char(char c) {
  return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' || c == '-' || c == '.';
}

// Length of the run of `quote` characters starting at i.
std::size_t run_of(std::string_view s, std::size_t i, char quote) {
  std::size_t n = 0;
  while (i + n < s.size() && s[i + n] == quote) ++n;
  return n;
}

}  // namespace

std::optional<UnsafeCharacter> find_unsafe_non_ascii(std::string_view s) {
  enum class State { normal, comment, basic, literal, multiline_basic, multiline_literal };
  // How much of the current line is `  key = ` (bare key), the only prefix of a trusted string.
  enum class Prefix { start, key, after_key, equals, broken };
  State state = State::normal;
  Prefix prefix = Prefix::start;
  long depth = 0;          // open [ and { (arrays, inline tables, headers) outside strings
  long depth_at_line = 0;  // depth when the line began
  bool trusted = false;    // the current string may hold non-ASCII
  long line = 1;
  std::size_t i = 0;
  if (s.substr(0, 3) == "\xEF\xBB\xBF") i = 3;  // byte order mark
  const auto unsafe = [&](const char* what) { return UnsafeCharacter{line, what}; };
  const auto new_line = [&] {
    ++line;
    prefix = Prefix::start;
    depth_at_line = depth;
  };
  while (i < s.size()) {
    const char c = s[i];
    switch (state) {
      case State::normal: {
        if (non_ascii(c)) return unsafe("non-ASCII character outside a string or comment");
        if (c == '\n') {
          new_line();
          break;
        }
        if (c == '"' || c == '\'') {
          trusted = (prefix == Prefix::equals) && depth_at_line == 0 && depth == 0;
          prefix = Prefix::broken;
          const std::size_t n = run_of(s, i, c);
          if (n == 2) {  // an empty string
            i += 2;
            continue;
          }
          const bool multiline = n >= 3;
          state = c == '"' ? (multiline ? State::multiline_basic : State::basic)
                           : (multiline ? State::multiline_literal : State::literal);
          i += multiline ? 3 : 1;
          continue;
        }
        if (c == '#') state = State::comment;
        if (c == '[' || c == '{') ++depth;
        if ((c == ']' || c == '}') && depth > 0) --depth;
        // Track `  key = ` at the line's start.
        if (blank(c)) {
          if (prefix == Prefix::key) prefix = Prefix::after_key;
        } else if (bare_key_char(c) && (prefix == Prefix::start || prefix == Prefix::key)) {
          prefix = Prefix::key;
        } else if (c == '=' && (prefix == Prefix::key || prefix == Prefix::after_key)) {
          prefix = Prefix::equals;
        } else {
          prefix = Prefix::broken;
        }
        break;
      }
      case State::comment:
        if (c == '\n') {
          state = State::normal;
          new_line();
        }
        break;
      case State::basic:
      case State::multiline_basic:
        if (non_ascii(c) && !trusted) return unsafe("non-ASCII character in a string that is not a key = \"value\"");
        if (c == '\n') {
          if (state == State::basic) {
            state = State::normal;
            new_line();
            break;
          }
          ++line;
        }
        if (c == '\\') {
          if (i + 1 < s.size() && non_ascii(s[i + 1])) return unsafe("non-ASCII character right after a backslash");
          if (state == State::multiline_basic && i + 1 < s.size() &&
              (s[i + 1] == ' ' || s[i + 1] == '\t' || s[i + 1] == '\r' || s[i + 1] == '\n')) {
            // A line-ending backslash: toml++ tests every character up to the next non-blank one.
            std::size_t j = i + 1;
            for (; j < s.size() && (s[j] == ' ' || s[j] == '\t' || s[j] == '\r' || s[j] == '\n'); ++j)
              if (s[j] == '\n') ++line;
            if (j < s.size() && non_ascii(s[j]))
              return unsafe("non-ASCII character first on a line continued by a backslash");
            i = j;
            continue;
          }
          if (i + 1 < s.size() && s[i + 1] == '\n') ++line;
          i += 2;
          continue;
        }
        if (state == State::basic && c == '"') state = State::normal;
        if (state == State::multiline_basic && c == '"' && run_of(s, i, '"') >= 3) {
          i += std::min<std::size_t>(run_of(s, i, '"'), 5);  // up to two quotes end the content
          state = State::normal;
          continue;
        }
        break;
      case State::literal:
      case State::multiline_literal:
        if (non_ascii(c) && !trusted) return unsafe("non-ASCII character in a string that is not a key = \"value\"");
        if (c == '\n') {
          if (state == State::literal) {
            state = State::normal;
            new_line();
            break;
          }
          ++line;
        }
        if (state == State::literal && c == '\'') state = State::normal;
        if (state == State::multiline_literal && c == '\'' && run_of(s, i, '\'') >= 3) {
          i += std::min<std::size_t>(run_of(s, i, '\''), 5);
          state = State::normal;
          continue;
        }
        break;
    }
    ++i;
  }
  return std::nullopt;
}

}  // namespace lrchain::config::detail
