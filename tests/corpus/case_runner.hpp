#pragma once
// Running one corpus case: a fresh working directory, lrchain spawned with an argv (ChildProcess),
// a timeout enforced by SIGTERM then SIGKILL, and the rules of bad input checked on the result.
#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include "corpus_case.hpp"

namespace lrchain::corpus {

struct RunSettings {
  std::string lrchain;                  // the program under test
  std::filesystem::path scratch;        // each case gets a fresh directory under this one
  std::chrono::milliseconds timeout{10000};
  std::vector<std::string> environment; // extra "NAME=value" entries for the child
  bool keep_directories = false;        // leave the case directories for inspection
};

struct BrokenRule {
  std::string rule;    // short, for grouping: "exit code", "timeout", "stderr lines", "names", "disk"
  std::string detail;  // what was seen
};

struct CaseOutcome {
  std::vector<BrokenRule> broken;  // empty: the case passed
  std::string command_line;        // argv as a shell would show it, with TMP for the directory
  std::string error_output;        // the child's stderr
  int exit_code = -1;              // -1 when killed
  int signal_number = 0;
  double seconds = 0;
};

CaseOutcome run_case(const CorpusCase& c, const RunSettings& settings);

// True when `text` names `name` as a whole word ("t-end" in "invalid t-end:", "--t-end" or "t_end",
// not in "t-end-x"); '_' and '-' count as the same letter.
bool names(const std::string& text, const std::string& name);

}  // namespace lrchain::corpus
