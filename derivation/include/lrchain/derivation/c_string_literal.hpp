#pragma once
// The one way text from outside the program (a model file's strings, a path) enters emitted C++:
// as a C string literal whose every byte outside printable ASCII, and every quote, backslash and
// question mark (trigraphs), is a three-digit octal escape. The literal itself is printable ASCII
// with no line break, so it can neither end a comment nor start a directive.
#include <string>
#include <string_view>

namespace lrchain::derivation {

// `text` as a C/C++ string literal, quotes included; any bytes (NUL, newlines, invalid UTF-8) allowed.
std::string c_string_literal(std::string_view text);

}  // namespace lrchain::derivation
