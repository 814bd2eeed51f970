#pragma once
// One case of the bad-input corpus, and the generators that build the corpus from the help texts,
// the shipped example configs and the tables of corpus_tables.hpp.
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "help_discovery.hpp"

namespace lrchain::corpus {

struct CorpusCase {
  std::string category;     // "option value", "config value", "config unknown key", "file", "output path", "control"
  std::string description;  // what is bad, e.g. "simulate bright --N=nan"
  std::string value;        // the corpus value (label(BadValue)), or "typo" / "" for other cases
  std::vector<std::string> args;  // after `lrchain`; "@TMP@" = the fresh working directory, "@OUT@" = @TMP@/out
  std::vector<std::pair<std::string, std::string>> files;  // created under @TMP@ before the run: path, bytes
  std::vector<std::string> directories;                    // created under @TMP@ before the run
  std::vector<std::string> names;       // the stderr line must name each (option, key, file)
  std::vector<std::string> any_name;    // ... and at least one of these (the option or the file)
  std::vector<std::string> substrings;  // ... and contain each literally (e.g. "exp1.toml:7")
  bool control = false;                 // a valid base command: must exit 0
};

struct Corpus {
  std::vector<CorpusCase> cases;
  std::map<std::string, int> skipped_as_valid;  // per category: values the option's range allows
  std::vector<std::string> errors;              // tables out of step with the help texts
};

// Every numeric option of every subcommand with every corpus value, plus the controls.
void add_option_cases(const std::vector<HelpCommand>& commands, Corpus& corpus);
// Every key of every examples/*.toml (one file per experiment kind and key) with every corpus
// value, and a typo of each key as an unknown key.
void add_config_cases(const std::filesystem::path& examples, const std::vector<HelpCommand>& commands,
                      Corpus& corpus);
// Missing, empty, binary, malformed files and directories where a file is read; outputs pointing
// at an existing path of the wrong kind.
void add_file_cases(const std::vector<HelpCommand>& commands, Corpus& corpus);
// Every key of the corpus's sweep files (tests/corpus/sweep_*.toml) with a wrong type, NaN, inf,
// -1, 0, 1e308 and the empty string, and misspelt; the base config they name missing, empty,
// binary, malformed or a directory.
void add_sweep_config_cases(const std::filesystem::path& corpus_dir, Corpus& corpus);
// Hostile model files (model_file_cases.cpp): control characters and invalid UTF-8 in every string,
// a device, a directory or an oversized file, unbounded expressions and a zero stiffness, through
// coeffs, derive, simulate ring and dark solve --model.
void add_model_file_cases(Corpus& corpus);

}  // namespace lrchain::corpus
