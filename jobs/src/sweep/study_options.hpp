#pragma once
// How a study sweep job's base table ([wave], [bright]) takes a job's options from its option schema
// (jobs/option_schema.hpp): which options, each as a typed key, and a refused one named in a point's reason.
// Private to jobs/src/sweep.
#include <string>
#include <string_view>
#include <vector>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/errors.hpp"
#include "lrchain/jobs/option_schema.hpp"

namespace lrchain::jobs::sweep {

// The options a sweep point of the job's subcommand `step` takes: those Python offers (not the output's
// nor the solver's).
bool sweep_option(const JobOption& o, std::string_view step);

// The option as a key of the base's table, under its Python name: a string (a string default, or the
// branch), a boolean, an integer or a number, with its default and meaning; required as the schema says.
lrchain::config::KeySchema sweep_option_key(const JobOption& o);

// `e`, thrown by the job's validate(), renamed for a point's reason: "[TABLE] KEY in FILE" with KEY the
// Python name of its Config key in `options` (`key` instead when given), its text without "invalid KEY: ".
InvalidParameter table_key_error(const lrchain::config::Document& doc, std::string_view table, const InvalidParameter& e,
                                 const std::vector<JobOption>& options, const std::string& key = "");

}  // namespace lrchain::jobs::sweep
