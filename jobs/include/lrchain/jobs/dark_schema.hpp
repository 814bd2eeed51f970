#pragma once
// The dark job's options once: each DarkConfig key with its default (read from a default DarkConfig),
// range and one-line documentation, and how each front end spells it (CLI option, Python keyword).
// `lrchain dark` builds its options' help from it and lrchain.dark takes its defaults from it.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lrchain::jobs::dark {

struct DarkOption {
  std::string key;             // DarkConfig key (snake_case), the name validate() reports
  std::string cli;             // `lrchain dark` option, e.g. "--omega-b" ("": not on the command line)
  std::string python;          // lrchain.dark keyword, e.g. "omega_b" ("": not in Python)
  std::vector<std::string> steps;  // the subcommands that take it: solve, floquet, continue, evolve
  nlohmann::json default_value;    // DarkConfig{}'s value; null: required or chosen by the job
  bool required = false;       // the command line requires it (Python: None picks a documented fallback)
  std::string range;           // the values validate() accepts, e.g. "odd, >= 9" ("": any)
  std::string doc;             // one line: what it is
};

// Every option of the dark job that a front end offers, in the order `lrchain dark --help` shows them.
const std::vector<DarkOption>& dark_options();

// The option of `key`; std::out_of_range if the schema has none.
const DarkOption& dark_option(const std::string& key);

// The help text of an option: its doc, range and default ("... [odd, >= 9; default 101]"; "default: none"
// when DarkConfig has none, "required" for a required option).
std::string help_text(const DarkOption& o);

// The default as the help shows it: 101, bond, 1e-11; "" when there is none.
std::string default_text(const DarkOption& o);

}  // namespace lrchain::jobs::dark
