// What defines a run's trajectory, as key = value items (checkpoint_store.hpp).
#include <charconv>
#include <string_view>
#include <system_error>

#include <fmt/format.h>

#include "lrchain/sha256.hpp"
#include "lrchain/sim/checkpoint_store.hpp"

#ifndef LRCHAIN_VERSION
#error "LRCHAIN_VERSION must be defined (sim/CMakeLists.txt passes the CMake project version)"
#endif

namespace lrchain::sim {

void TrajectoryIdentity::add(const std::string& key, double value) {
  items_.emplace_back(key, fmt::format("{}", value));
}
void TrajectoryIdentity::add(const std::string& key, long value) {
  items_.emplace_back(key, std::to_string(value));
}
void TrajectoryIdentity::add(const std::string& key, const std::string& value) {
  items_.emplace_back(key, value);
}
void TrajectoryIdentity::add(const std::string& key, double value, ShownAs shown) {
  add(key, value);
  shown_.emplace_back(key, std::move(shown));
}
void TrajectoryIdentity::add(const std::string& key, long value, ShownAs shown) {
  add(key, value);
  shown_.emplace_back(key, std::move(shown));
}
void TrajectoryIdentity::add_state_hash(const std::string& key, const State& state) {
  const std::string_view bytes(reinterpret_cast<const char*>(state.data()), state.size() * sizeof(double));
  items_.emplace_back(key, "sha256:" + sha256_hex(bytes));
}

std::string TrajectoryIdentity::text() const {
  std::string t = std::string("lrchain_version = ") + LRCHAIN_VERSION + "\n";
  for (const auto& [k, v] : items_) t += k + " = " + v + "\n";
  return t;
}

std::string TrajectoryIdentity::shown(const std::string& key, const std::string& value) const {
  for (const auto& [k, s] : shown_) {
    if (k != key) continue;
    if (!s.value) return s.name + " = " + value;
    long recorded = 0;
    const char* end = value.data() + value.size();
    const auto [at, error] = std::from_chars(value.data(), end, recorded);
    if (error == std::errc() && at == end) return s.name + " = " + std::to_string(s.value(recorded));
    break;  // not a long: shown as recorded
  }
  return key + " = " + value;
}

}  // namespace lrchain::sim
