#pragma once
// Where lrchain finds the data it ships (examples/, models/, docs/paper-errata.md): an installed
// lrchain in <prefix>/share/lrchain beside its bin/; a build tree's lrchain in the source tree named
// by the file lrchain-source-tree next to it (written by cli/CMakeLists.txt, never installed).
#include <filesystem>
#include <string>
#include <vector>

namespace lrchain::cli {

// The directories to look in for shipped data, in order: <prefix>/share/lrchain (from
// /proc/self/exe), then the source tree when this lrchain runs from its build tree.
std::vector<std::filesystem::path> shipped_data_roots();

// --model ARG as a path: ARG itself when it has a '/', ends in .toml or names a file; otherwise the
// shipped model ARG, models/ARG.toml under the first of shipped_data_roots() that has it. InputError
// (exit 2) naming the shipped models when there is none of that name.
std::string resolve_model_argument(const std::string& text);

}  // namespace lrchain::cli
