#pragma once
// The parts of `lrchain ... --help` that every subcommand shares: the exit codes, an example
// command line (footer), the one-line message for a command given without its subcommand, and
// the paper's equations cited by number.
#include <CLI/CLI.hpp>
#include <string>

#include "report/rich_text.hpp"

namespace lrchain::cli {

// The exit codes of every lrchain command (lrchain/exit_codes.hpp), as the help shows them.
inline std::string exit_codes_text() {
  return "Exit codes: 0 success; 1 another error (e.g. a file could not be written); 2 bad input or a\n"
         "job too large for the machine (one line on stderr names the option; nothing written);\n"
         "3 numerical failure (blow-up of a lattice run, Newton not converging; also in the JSON);\n"
         "130/143 interrupted by SIGINT/SIGTERM.";
}

// Sets the help footer of `cmd` to its examples (one command line each) and the exit codes.
inline void add_examples(CLI::App& cmd, std::initializer_list<std::string> examples) {
  std::string text = examples.size() > 1 ? "Examples:\n" : "Example:\n";
  bool example_files = false;
  for (const auto& e : examples) {
    text += "  " + e + "\n";
    example_files = example_files || e.find(" examples/") != std::string::npos;
  }
  if (example_files)
    text += "(examples/ is the source tree's; an installed lrchain has it in <prefix>/share/lrchain/examples)\n";
  cmd.footer(text + "\n" + exit_codes_text());
}

// "lrchain regime: give a subcommand: intervals, map, thresholds (see lrchain regime --help)":
// the message for the deepest command of a parsed command line that needs a subcommand and got
// none; empty when no such command was given.
inline std::string missing_subcommand_message(const CLI::App& app) {
  const CLI::App* deepest = &app;
  std::string path = "lrchain";
  for (;;) {
    const auto parsed = deepest->get_subcommands();
    if (parsed.empty()) break;
    deepest = parsed.front();
    path += " " + deepest->get_name();
  }
  const auto available = deepest->get_subcommands([](const CLI::App*) { return true; });
  if (available.empty() || !deepest->get_subcommands().empty()) return {};
  std::string names;
  for (const CLI::App* sub : available) names += (names.empty() ? "" : ", ") + sub->get_name();
  return path + ": give a subcommand: " + names + " (see " + path + " --help)";
}

// Cites the paper's equations and figures by their printed numbers ("eq:focus_app" -> "eq. (38)")
// in the descriptions of `cmd`, its options and all its subcommands.
inline void cite_paper_numbers(CLI::App& cmd) {
  cmd.description(report::plain_citations(cmd.get_description()));
  for (CLI::Option* option : cmd.get_options()) option->description(report::plain_citations(option->get_description()));
  for (CLI::App* sub : cmd.get_subcommands([](const CLI::App*) { return true; })) cite_paper_numbers(*sub);
}

}  // namespace lrchain::cli
