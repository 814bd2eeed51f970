#pragma once
// The exact bright-breather job's options once: each BrightBreatherConfig key with its default (read
// from a default BrightBreatherConfig), range and one-line documentation, and how each front end spells
// it. `lrchain bright` builds its options' help from it and lrchain.bright takes its defaults from it.
#include <string>
#include <vector>

#include "lrchain/jobs/option_schema.hpp"

namespace lrchain::jobs::bright_breather {

// Every option of the job that a front end offers, in the order `lrchain bright --help` shows them;
// `steps` are the subcommands that take it: solve, floquet.
const std::vector<JobOption>& bright_breather_options();

// The option of `key`; std::out_of_range if the schema has none.
const JobOption& bright_breather_option(const std::string& key);

}  // namespace lrchain::jobs::bright_breather
