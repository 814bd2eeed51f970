// The "did you mean" of config messages (strict_toml.hpp): nearest valid key by edit distance.
#include <algorithm>
#include <cctype>
#include <vector>

#include "lrchain/config/strict_toml.hpp"

namespace lrchain::config {

namespace {

std::string lower(std::string_view s) {
  std::string r(s);
  for (char& c : r) c = char(std::tolower(static_cast<unsigned char>(c)));
  return r;
}

// Optimal string alignment distance (Levenshtein plus adjacent transpositions).
std::size_t osa_distance(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

}  // namespace

std::string closest_match(std::string_view word, const std::vector<std::string>& candidates) {
  const std::string w = lower(word);
  std::string best;
  std::size_t best_distance = 0;
  for (const auto& candidate : candidates) {
    const std::string c = lower(candidate);
    if (c == w) return candidate;  // differs only in case
    // A typo changes at most a third of the word (at least one letter), and not all of it.
    const std::size_t allowed = std::max<std::size_t>(1, c.size() / 3);
    const std::size_t length_gap = c.size() > w.size() ? c.size() - w.size() : w.size() - c.size();
    if (length_gap > allowed) continue;
    const std::size_t d = osa_distance(w, c);
    if (d > allowed || d >= w.size()) continue;
    if (best.empty() || d < best_distance) {
      best = candidate;
      best_distance = d;
    }
  }
  return best;
}

}  // namespace lrchain::config
