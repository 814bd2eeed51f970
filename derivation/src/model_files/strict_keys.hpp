#pragma once
// The one place where a model file's tables are checked for unknown keys (swap for the library's
// strict-config layer once it exists): a misspelt key is named with its line and the closest valid key.
#include <toml++/toml.h>

#include <string>
#include <vector>

namespace lrchain::derivation {

// Closest candidate by edit distance ("" when none is within max(1, length/3) edits).
std::string closest_name(const std::string& word, const std::vector<std::string>& candidates);

// Throws lrchain::InputError "FILE:LINE: unknown key 'K' in WHERE (allowed: ...; did you mean 'X'?)"
// for the first key of `table` not in `allowed`.
void reject_unknown_keys(const toml::table& table, const std::vector<std::string>& allowed, const std::string& file,
                         const std::string& where);

}  // namespace lrchain::derivation
