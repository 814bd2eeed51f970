#pragma once
// The dark job's options once: each DarkConfig key with its default (read from a default DarkConfig),
// range and one-line documentation, and how each front end spells it (CLI option, Python keyword).
// `lrchain dark` builds its options' help from it and lrchain.dark takes its defaults from it.
#include <string>
#include <vector>

#include "lrchain/jobs/option_schema.hpp"

namespace lrchain::jobs::dark {

// One option of the dark job (option_schema.hpp); `steps` are the subcommands that take it: solve,
// floquet, continue, evolve.
using DarkOption = JobOption;

// Every option of the dark job that a front end offers, in the order `lrchain dark --help` shows them.
const std::vector<DarkOption>& dark_options();

// The option of `key`; std::out_of_range if the schema has none.
const DarkOption& dark_option(const std::string& key);

}  // namespace lrchain::jobs::dark
