#include "strict_keys.hpp"

#include <algorithm>

#include "lrchain/errors.hpp"

namespace lrchain::derivation {

namespace {
// Levenshtein distance (insertions, deletions, substitutions).
std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}
}  // namespace

std::string closest_name(const std::string& word, const std::vector<std::string>& candidates) {
  std::string best;
  std::size_t best_distance = std::max<std::size_t>(1, word.size() / 3) + 1;  // accept up to size/3 edits
  for (const auto& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
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
