#pragma once
// A key or option that was renamed (config schemas, strict_toml.hpp; Python's run option dicts).
#include <string>

namespace lrchain::config {

// The old name is an error naming the new one, followed by `note` when the meaning changed too
// ("the number of strain sites 2N + 1 (the old N was the half-width)").
struct RenamedKey {
  std::string old_name, new_name;
  std::string note = {};

  // What a message offers instead of the old name: "'sites', <note>" (or "'sites'" without a note).
  std::string replacement() const { return "'" + new_name + "'" + (note.empty() ? "" : ", " + note); }
};

}  // namespace lrchain::config
