#pragma once
// Provenance (lrchain/provenance.hpp) as the "provenance" object of a JSON summary; header-only so
// that the core library does not depend on nlohmann-json. Unknown values are null.
#include <nlohmann/json.hpp>

#include "lrchain/provenance.hpp"

namespace lrchain {

inline nlohmann::json provenance_json(const Provenance& p) {
  auto or_null = [](const std::string& s) { return s.empty() ? nlohmann::json(nullptr) : nlohmann::json(s); };
  return {{"lrchain_version", p.build.version},
          {"git_commit", or_null(p.build.commit)},
          {"compiler", or_null(p.build.compiler)},
          {"build_type", or_null(p.build.build_type)},
          {"cores", p.cores > 0 ? nlohmann::json(p.cores) : nlohmann::json(nullptr)},
          {"date", p.date},
          {"command_line", p.command_line.empty() ? nlohmann::json(nullptr) : nlohmann::json(p.command_line)}};
}

// The provenance of a result produced now by this process.
inline nlohmann::json provenance_json() { return provenance_json(current_provenance()); }

}  // namespace lrchain
