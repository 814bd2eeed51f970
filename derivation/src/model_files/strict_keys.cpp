#include "strict_keys.hpp"

#include <algorithm>

#include "lrchain/config/strict_toml.hpp"
#include "lrchain/errors.hpp"

namespace lrchain::derivation {

// The valid name nearest to `word` by edit distance (the config layer's rule), empty if none is close.
std::string closest_name(const std::string& word, const std::vector<std::string>& candidates) {
  return config::closest_match(word, candidates);
}

void reject_unknown_keys(const toml::table& table, const std::vector<std::string>& allowed, const std::string& file,
                         const std::string& where) {
  for (const auto& [key, node] : table) {
    const std::string name(key.str());
    if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
    std::string list;
    for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
    const std::string guess = closest_name(name, allowed);
    const auto line = key.source().begin.line ? key.source().begin.line : node.source().begin.line;
    throw InputError(file + ":" + std::to_string(line) + ": unknown key '" + name + "' in " + where + " (allowed: " +
                     list + (guess.empty() ? ")" : "; did you mean '" + guess + "'?)"));
  }
}

}  // namespace lrchain::derivation
