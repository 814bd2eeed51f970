#pragma once
// Text from a user (a sweep's name, a model's name, a file name) in a gnuplot script: always as a
// single-quoted gnuplot string made by gnuplot_text, never as script text. Inside single quotes
// gnuplot substitutes nothing (no `backquote` commands, no @macros, no backslash escapes; inside
// double quotes it does run backquoted commands); only a quote ends the string and a line break
// ends the command. gnuplot's own escape for a quote (two quotes) is misread by gnuplot 5.4 when
// two such pairs come together, so a quote is shown as the typographic apostrophe U+2019 instead,
// and every control character (bytes 0-31 and 127) as U+FFFD: the string holds no quote and no
// line break. In enhanced text mode (the terminal's default) the characters enhanced text
// interprets (\ _ ^ @ & ~ { }) are escaped with a backslash so that the text is shown as written.
#include <string>
#include <string_view>

namespace lrchain::jobs {

enum class GnuplotTextMode {
  plain,     // a `noenhanced` terminal, a file name, a variable's value
  enhanced,  // a title or label on an enhanced-text terminal
};

// `text` as the inside of a single-quoted gnuplot string (the caller writes the quotes).
std::string gnuplot_text(std::string_view text, GnuplotTextMode mode = GnuplotTextMode::plain);

// `text` as a whole single-quoted gnuplot string, quotes included (plain mode).
std::string gnuplot_string(std::string_view text);

// A file name relative to the script's directory as a gnuplot string: "./" goes in front, so that
// a name starting with '<' (gnuplot: read a shell command's output) or '|' (write into one) is a
// file. (A name with a quote or a control character cannot reach gnuplot as it is: callers refuse
// such names first.)
std::string gnuplot_file_name(std::string_view name);

}  // namespace lrchain::jobs
