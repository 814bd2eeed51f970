#pragma once
// Wall-clock seconds since a start time, for the timings a regime job reports.
#include <chrono>

namespace lrchain::jobs {

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace lrchain::jobs
