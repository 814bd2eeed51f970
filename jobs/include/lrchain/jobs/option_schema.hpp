#pragma once
// One option of a job, once: its Config key with default, range and one-line documentation, and how each
// front end spells it (CLI option, Python keyword). Every job has one list of these (job_options): the
// CLI builds its options' help from it, Python takes its defaults and docstrings from it, and the tests
// compare both with it (tests/python/test_job_schemas.py).
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "lrchain/errors.hpp"

namespace lrchain::jobs {

struct JobOption {
  std::string key;                 // Config key (snake_case), the name validate() reports
  std::string cli;                 // the command's option, e.g. "--omega-b" ("": not on the command line)
  std::string python;              // the Python keyword, e.g. "omega_b" ("": not in Python)
  std::vector<std::string> steps;  // the subcommands that take it (empty: the job has one command)
  nlohmann::json default_value;    // the default Config's value; null: required or chosen by the job
  bool required = false;           // the command line requires it (Python then takes the default, if any)
  std::string range;               // the values validate() accepts, e.g. "odd, >= 9" ("": any)
  std::string doc;                 // one line: what it is
  // The CLI's help where it is not "doc [range; default D]": a text in which {range} and {default}
  // stand for range and default_text() ("": that form).
  std::string help = {};
  // The default as the help states it where the value alone would not do: when the Config has none
  // (the job chooses it, e.g. "sign(h_tilde)*1e-4") or to spell it (pi/2); "": the value, or "none".
  std::string default_note = {};
};

// The schema that `Make` builds, built once: what a job's accessor (e.g. bright_options()) returns.
template <std::vector<JobOption> (*Make)()>
const std::vector<JobOption>& schema_once() {
  static const std::vector<JobOption> options = Make();
  return options;
}

// The options of one job (e.g. "bright", "dark", "regime intervals", "coeffs") in the order its
// `--help` shows them; std::out_of_range for a job that has none.
const std::vector<JobOption>& job_options(const std::string& job);

// Every job that has an option schema, e.g. {"bright", "coeffs", "dark", ...}.
std::vector<std::string> job_names();

// The option of `key` in `options`; std::out_of_range if there is none.
const JobOption& find_option(const std::vector<JobOption>& options, const std::string& key);

// The default as the help shows it: default_note if any, else 101, bond, 1e-11, "0 50.125 200" for a
// list ("" when the Config has none).
std::string default_text(const JobOption& o);

// The CLI's help text of an option: `help` with its {range} and {default} filled in, or "doc [range;
// default D]" ("default: none" when the Config has none, "required" for a required option).
std::string help_text(const JobOption& o);

// One option as JSON: {key, cli, python, steps, default, required, range, doc, help, default_text}
// (what Python reads: _lrchain.job_options).
nlohmann::json to_json(const JobOption& o);

// The command-line name of a job's Config key: its option in `options` without the "--" (snapshot_periods
// -> snapshots), else the key with '_' read as '-' (t_end -> t-end).
std::string cli_name(const std::vector<JobOption>& options, const std::string& key);

// `e` naming `name` instead of its key, its text kept: "invalid t_end: ..." -> "invalid t-end: ...".
InvalidParameter renamed_parameter(const InvalidParameter& e, const std::string& name);

}  // namespace lrchain::jobs
