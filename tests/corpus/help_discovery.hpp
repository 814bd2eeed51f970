#pragma once
// The command tree of `lrchain` as its --help texts describe it: every subcommand (nested ones like
// `regime map`), every option with its type name, arity and the valid range its help states.
#include <optional>
#include <string>
#include <vector>

namespace lrchain::corpus {

// The set of values an option's help allows, as far as the help says: intersections of
// "> a", ">= a", "in (a, b]", CLI11's "in [a - b]", plus "0: ..." (zero has a meaning).
struct StatedRange {
  double lo = -1e300, hi = 1e300;
  bool lo_open = false, hi_open = false;
  bool zero_allowed = false;  // "0: none", "0: one per core"
  bool stated = false;        // false: the help gives no range
  bool contains(double v) const;
};

struct HelpOption {
  std::string name;         // without dashes: "theta", "t-end", "N"
  std::string type;         // CLI11 type name before any ':' ("NUM", "INT", "TEXT", ""), empty for flags
  int arity = 1;            // 1, 2 ("TEXT x 2"), -1 (a list, "FLOAT ...")
  bool required = false;    // "REQUIRED"
  std::string help;         // signature after the name, and the description
  StatedRange range;
  bool is_numeric() const;  // NUM, INT, UINT, FLOAT, DOUBLE
  bool is_integer() const;  // INT, UINT
};

struct HelpCommand {
  std::vector<std::string> path;  // {"regime", "map"}; empty for the top level
  std::vector<HelpOption> options;
  std::vector<std::string> subcommands;
  std::string joined() const;     // "regime map"
  const HelpOption* find(const std::string& option_name) const;
};

// Parses one --help text (CLI11's layout: "Options:" and "Subcommands:" sections).
HelpCommand parse_help(const std::vector<std::string>& path, const std::string& text);

// Runs `lrchain [path] --help` for the top level and, recursively, every subcommand.
// Throws std::runtime_error when a help cannot be obtained.
std::vector<HelpCommand> discover_commands(const std::string& lrchain);

// The range stated in an option's help text (exposed for the parser's own check).
StatedRange parse_stated_range(const std::string& help);

}  // namespace lrchain::corpus
