#pragma once
// Provenance of a result: which lrchain produced it (version, git commit, compiler, build type),
// on which machine (cores), when, and from which command line. Every JSON summary and the report
// of `lrchain reproduce` carry it (lrchain/provenance_json.hpp).
#include <string>
#include <vector>

#include "lrchain/index.hpp"
#include "lrchain/version.hpp"

namespace lrchain {

// Fixed when lrchain was built.
struct BuildInfo {
  std::string version;     // e.g. "0.1.0"
  std::string commit;      // git commit of the source tree, "<hash>[-dirty]"; "" outside a checkout
  std::string compiler;    // e.g. "GNU 12.2.0"
  std::string build_type;  // CMake build type, e.g. "Release"; "" when none was set
};
BuildInfo build_info();

struct Provenance {
  BuildInfo build;
  Index cores = 0;                        // hardware threads of this machine
  std::string date;                       // now, ISO 8601 UTC ("2026-11-23T16:40:00Z")
  std::vector<std::string> command_line;  // argv of this process; empty when it cannot be read
};
// The provenance of a result produced now by this process.
Provenance current_provenance();

// "lrchain 0.1.0 (commit 1a2b3c4d5e6f)", commit "unknown" outside a git checkout.
std::string version_line();

}  // namespace lrchain
