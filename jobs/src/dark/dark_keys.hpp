#pragma once
// The dark job's refusals name DarkConfig keys (snake_case): a check of lib/ or sim/ that names the
// command's option (InvalidParameter("omega-b")) is re-thrown with the key ("omega_b"), its text kept.
#include <string>

#include "lrchain/errors.hpp"

namespace lrchain::jobs::dark {

// `e` re-named by `key`, with its text after "invalid <parameter>: ".
inline InvalidParameter renamed(const InvalidParameter& e, const std::string& key) {
  const std::string text = e.what(), prefix = "invalid " + e.parameter() + ": ";
  return InvalidParameter(key, text.rfind(prefix, 0) == 0 ? text.substr(prefix.size()) : text);
}

// Runs `check`; an InvalidParameter naming an option with '-' is re-thrown naming the key with '_'.
template <class Check>
auto with_config_keys(Check&& check) {
  try {
    return check();
  } catch (const InvalidParameter& e) {
    std::string key = e.parameter();
    if (key.find('-') == std::string::npos) throw;
    for (char& c : key)
      if (c == '-') c = '_';
    throw renamed(e, key);
  }
}

}  // namespace lrchain::jobs::dark
