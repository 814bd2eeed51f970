#pragma once
// One line of printable UTF-8 text: what a name, a description or a path that lrchain reads from a
// file or an option must be (model files, sweep files). Refuses C0 controls and DEL (newline,
// carriage return, NUL, escape), the C1 controls U+0080..U+009F, the separators U+2028/U+2029 and
// bytes that are not UTF-8 (RFC 3629).
#include <string>
#include <string_view>

namespace lrchain {

// Why `text` is not one line of printable UTF-8 ("a control character (byte 0x0a)", "a control
// character (U+0085)", "a byte that is not valid UTF-8 (0xff)", ...), or "" when it is.
std::string one_line_text_problem(std::string_view text);

}  // namespace lrchain
