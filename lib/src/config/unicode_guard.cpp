// Finding the non-ASCII characters toml++ 3.3 cannot parse safely (unicode_guard.hpp): a small
// TOML tokenizer that follows comments and the four kinds of strings.
#include "unicode_guard.hpp"

namespace lrchain::config::detail {

namespace {

bool non_ascii(char c) { return static_cast<unsigned char>(c) >= 0x80; }

// Length of the run of `quote` characters starting at i.
std::size_t run_of(std::string_view s, std::size_t i, char quote) {
  std::size_t n = 0;
  while (i + n < s.size() && s[i + n] == quote) ++n;
  return n;
}

}  // namespace

std::optional<UnsafeCharacter> find_unsafe_non_ascii(std::string_view s) {
  enum class State { normal, comment, basic, literal, multiline_basic, multiline_literal };
  State state = State::normal;
  long line = 1;
  std::size_t i = 0;
  if (s.substr(0, 3) == "\xEF\xBB\xBF") i = 3;  // byte order mark
  // A quote opens a string only where TOML allows one: after '=', '[', ',', '{' or at a line's
  // start, and not inside a token (a run of other characters up to a blank, newline, ']', '}', ','
  // or '#'). toml++ reads a quote inside a malformed value as part of it and scans on to the next
  // such terminator, testing each character for whitespace, so that text stays outside strings here.
  char previous = '\n';
  bool in_token = false;
  const auto unsafe = [&](const char* what) { return UnsafeCharacter{line, what}; };
  while (i < s.size()) {
    const char c = s[i];
    if (c == '\n') ++line;
    switch (state) {
      case State::normal: {
        if (non_ascii(c)) return unsafe("non-ASCII character outside a string or comment");
        const bool string_may_start =
            !in_token && (previous == '=' || previous == '[' || previous == ',' || previous == '{' || previous == '\n');
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ']' || c == '}' || c == ',' || c == '#' || c == '=')
          in_token = false;
        else if (c != '[' && c != '{' && c != '"' && c != '\'')
          in_token = true;
        if (c != ' ' && c != '\t' && c != '\r') previous = c;
        if (c == '#') state = State::comment;
        if ((c == '"' || c == '\'') && string_may_start) {
          const std::size_t n = run_of(s, i, c);
          const bool multiline = n >= 3;
          state = c == '"' ? (multiline ? State::multiline_basic : State::basic)
                           : (multiline ? State::multiline_literal : State::literal);
          if (n == 2) {  // an empty string
            state = State::normal;
            i += 2;
            continue;
          }
          i += multiline ? 3 : 1;
          continue;
        }
        break;
      }
      case State::comment:
        if (c == '\n') {
          state = State::normal;
          previous = '\n';
        }
        break;
      case State::basic:
      case State::multiline_basic:
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
        if (state == State::basic && (c == '"' || c == '\n')) {
          state = State::normal;
          previous = c;
        }
        if (state == State::multiline_basic && c == '"' && run_of(s, i, '"') >= 3) {
          i += std::min<std::size_t>(run_of(s, i, '"'), 5);  // up to two quotes end the content
          state = State::normal;
          previous = '"';
          continue;
        }
        break;
      case State::literal:
        if (c == '\'' || c == '\n') {
          state = State::normal;
          previous = c;
        }
        break;
      case State::multiline_literal:
        if (c == '\'' && run_of(s, i, '\'') >= 3) {
          i += std::min<std::size_t>(run_of(s, i, '\''), 5);
          state = State::normal;
          previous = '\'';
          continue;
        }
        break;
    }
    ++i;
  }
  return std::nullopt;
}

}  // namespace lrchain::config::detail
