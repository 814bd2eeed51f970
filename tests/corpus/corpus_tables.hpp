#pragma once
// The only hand-written data of the bad-input corpus: a cheap valid command line per subcommand
// (the "base" each bad value is put into; each base is also run as a control that must exit 0),
// the options and config keys whose valid range includes some of the corpus values, and where
// files are taken. Everything else is generated from `lrchain --help` and examples/*.toml.
#include <map>
#include <set>
#include <string>
#include <vector>

namespace lrchain::corpus {

// The corpus values (issue: NaN, inf, -inf, -1, 0, 1e308, 1e300pi, empty, a word, a wrong type).
enum class BadValue { nan, inf, minus_inf, minus_one, zero, huge, huge_pi, empty, word, wrong_type };
inline constexpr BadValue kAllBadValues[] = {BadValue::nan,     BadValue::inf,   BadValue::minus_inf,
                                              BadValue::minus_one, BadValue::zero, BadValue::huge,
                                              BadValue::huge_pi, BadValue::empty, BadValue::word,
                                              BadValue::wrong_type};
const char* label(BadValue v);

// "@TMP@" in an argument is the case's fresh working directory (absolute), "@OUT@" is @TMP@/out.
// Bases are small and fast (each runs in well under a second) so that a bad value that is wrongly
// accepted ends quickly instead of running into the timeout.
const std::map<std::string, std::vector<std::string>>& base_commands();

// Extra arguments an option needs to be read at all (delta0-omega plane options).
const std::map<std::string, std::vector<std::string>>& option_context();

// Options with two values (lo hi): the valid lower value the bad upper value is paired with.
const std::map<std::string, std::string>& pair_partner();

// Options that take numbers although their help types them as TEXT.
const std::set<std::string>& numeric_text_options();

// Values that may be valid for an option or config key (dash form, e.g. "switch-off-time", "snapshots"),
// although its help states no range that says so. These cases are not run.
const std::set<BadValue>& possibly_valid(const std::string& name);

// Config keys named differently from the option that shares their range.
std::string option_for_config_key(const std::string& key);

// Where a file or directory is read: option -> command (the base it is put into).
struct FileOption {
  std::string command;  // "simulate modulated"
  std::string option;   // "restart"
  bool directory;       // the option takes a directory (reproduce --examples)
};
const std::vector<FileOption>& file_options();

// Output locations (--out, --checkpoint): given an existing path of the wrong kind they must fail.
struct OutputOption {
  std::string command;
  std::string option;
  bool is_file;  // --checkpoint names a file: a directory there is wrong; --out: a file is wrong
};
const std::vector<OutputOption>& output_options();

// The corpus's valid sweep files (in tests/corpus), which hold every key of a sweep file.
const std::vector<std::string>& sweep_config_files();

// examples/*.toml "experiment" kind -> the subcommand whose options share the keys' ranges.
std::string command_for_experiment(const std::string& kind);

}  // namespace lrchain::corpus
