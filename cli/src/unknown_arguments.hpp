#pragma once
// The one-line message for a command line with a word no command took: a misspelled option or
// subcommand, or a stray value. It wins over every other complaint about the same command line
// (a "required" option is usually just the misspelled one).
#include <CLI/CLI.hpp>
#include <string>

namespace lrchain::cli {

// "lrchain simulate bright: unknown option --brnach; did you mean --branch?" for the first word of
// the parsed command line `app` that no command took, with the closest valid option or subcommand
// name (lrchain::config::closest_match); empty when every word was taken.
std::string unknown_argument_message(const CLI::App& app);

}  // namespace lrchain::cli
