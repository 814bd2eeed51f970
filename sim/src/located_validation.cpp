// Run checks of a simulate config reported at the file's line of the key (located_validation.hpp).
#include "located_validation.hpp"

#include <algorithm>

#include "lrchain/errors.hpp"

namespace lrchain::sim::config {

void validate_located(const lrchain::config::CheckedTable& root, const std::string& experiment_table,
                      const std::function<void()>& validate) {
  try {
    validate();
  } catch (const InvalidParameter& e) {
    std::string key = e.parameter();
    std::replace(key.begin(), key.end(), '-', '_');
    for (const std::string& name : {experiment_table, std::string("model"), std::string("integrator")}) {
      const auto table = root.table(name);
      if (!table || !table->has(key)) continue;
      const long line = table->line(key);
      if (line <= 0) break;  // a value set by a program (a sweep point), not written in the file
      // "invalid theta: must be ..." -> "must be ..."
      const std::string prefix = "invalid " + e.parameter() + ": ";
      std::string allowed = e.what();
      if (allowed.starts_with(prefix)) allowed.erase(0, prefix.size());
      throw lrchain::config::ConfigError("invalid value for '" + key + "' in [" + table->path() + "] at " +
                                             root.source() + ":" + std::to_string(line) + ": " + allowed,
                                         root.source(), line, table->path(), key);
    }
    throw;
  }
}

}  // namespace lrchain::sim::config
