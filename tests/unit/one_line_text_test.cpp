// one_line_text_problem (lrchain/one_line_text.hpp), the check of names, descriptions and paths read
// from model and sweep files. Expected classes: C0 controls and DEL (ASCII), C1 controls
// U+0080..U+009F and U+2028/U+2029 (Unicode's line-breaking controls), and RFC 3629's UTF-8
// (no lone continuation bytes, no overlongs, no surrogates).
#include <doctest/doctest.h>

#include <string>

#include "lrchain/one_line_text.hpp"

using lrchain::one_line_text_problem;

TEST_CASE("one_line_text_problem: every single byte, C1 controls, line separators and valid UTF-8") {
  for (int b = 0; b < 256; ++b) {
    CAPTURE(b);
    const std::string text(1, static_cast<char>(b));
    const bool printable_ascii = b >= 0x20 && b < 0x7f;
    CHECK(one_line_text_problem(text).empty() == printable_ascii);  // 0x80..0xff alone are not UTF-8
  }
  CHECK(one_line_text_problem("a\xc2\x85" "b") == "a control character (U+0085)");  // NEL
  CHECK(one_line_text_problem("\xc2\x9b") == "a control character (U+009b)");       // CSI
  CHECK(one_line_text_problem("a\xe2\x80\xa8" "b") == "a line or paragraph separator (U+2028)");
  CHECK(one_line_text_problem("\xe2\x80\xa9") == "a line or paragraph separator (U+2029)");
  CHECK(one_line_text_problem("\xc0\xaf").find("not valid UTF-8") != std::string::npos);  // overlong '/'
  CHECK(one_line_text_problem("\xed\xa0\x80").find("not valid UTF-8") != std::string::npos);  // a surrogate
  // Legal text: Latin, Greek, typographic quotes (U+2019), U+00A0 and an emoji.
  CHECK(one_line_text_problem("Morse chain: \xc3\xa9t\xc3\xa9, \xcf\x89 = \xe2\x80\x99x\xe2\x80\x99 \xc2\xa0 \xf0\x9f\x8c\x8a").empty());
}
