#pragma once
// Text from a user (a sweep's name, a model's name, a file name) in a gnuplot script: always as a
// single-quoted gnuplot string made by gnuplot_text, never as script text. Inside single quotes
// gnuplot substitutes nothing (no `backquote` commands, no @macros, no backslash escapes); only a
// quote ends the string ('' stands for one) and a line break ends the command, so a quote is
// doubled and every control character (bytes 0-31 and 127) is shown as U+FFFD. In enhanced text
// mode (the terminal's default) the characters enhanced text interprets (\ _ ^ @ & ~ { }) are
// escaped with a backslash so that the text is shown as written.
#include <string>
#include <string_view>

namespace lrchain::sim {

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
// file.
std::string gnuplot_file_name(std::string_view name);

}  // namespace lrchain::sim
