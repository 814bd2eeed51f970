// Run checks of a simulate config reported at the file's line of the key (located_validation.hpp).
#include "located_validation.hpp"

#include <algorithm>

#include "lrchain/errors.hpp"

namespace lrchain::jobs::config {

namespace {

// The key an InvalidParameter names: its option spelling with '-' read as '_'.
std::string key_of(const InvalidParameter& e) {
  std::string key = e.parameter();
  std::replace(key.begin(), key.end(), '-', '_');
  return key;
}

// Throws the ConfigError of `e` at `key`'s line in `table` when the file wrote the key there;
// returns when it did not (absent, or a value set by a program such as a sweep point).
void throw_located(const lrchain::config::CheckedTable& table, const std::string& key, const InvalidParameter& e) {
  if (!table.has(key)) return;
  const long line = table.line(key);
  if (line <= 0) return;
  // "invalid theta: must be ..." -> "must be ..."
  const std::string prefix = "invalid " + e.parameter() + ": ";
  std::string allowed = e.what();
  if (allowed.starts_with(prefix)) allowed.erase(0, prefix.size());
  throw lrchain::config::ConfigError("invalid value for '" + key + "' in [" + table.path() + "] at " + table.source() +
                                         ":" + std::to_string(line) + ": " + allowed,
                                     table.source(), line, table.path(), key);
}

}  // namespace

void validate_located(const lrchain::config::CheckedTable& root, const std::string& experiment_table,
                      const std::function<void()>& validate) {
  try {
    validate();
  } catch (const InvalidParameter& e) {
    const std::string key = key_of(e);
    for (const std::string& name : {experiment_table, std::string("model"), std::string("integrator")}) {
      const auto table = root.table(name);
      if (!table || !table->has(key)) continue;
      throw_located(*table, key, e);
      break;
    }
    throw;
  }
}

void validate_located(const lrchain::config::CheckedTable& table, const std::function<void()>& validate) {
  try {
    validate();
  } catch (const InvalidParameter& e) {
    throw_located(table, key_of(e), e);
    throw;
  }
}

}  // namespace lrchain::jobs::config
