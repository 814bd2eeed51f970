#pragma once
// A long call's progress reported to a Python callable `progress(fraction)` (lrchain/progress.py's
// bar), from C++ code running without the GIL: at most every 0.2 s and always at the end.
#include <chrono>
#include <functional>

#include <pybind11/pybind11.h>

namespace lrchain::python {

class ProgressHook {
 public:
  explicit ProgressHook(pybind11::object callback) : callback_(std::move(callback)) {}
  // The hook for RunControl::progress (empty when the callback is None): fraction in [0, 1].
  std::function<void(double)> hook();
  // Reports `fraction` now (with the GIL), unless the last report was under 0.2 s ago and it is not 1.
  void report(double fraction);

 private:
  pybind11::object callback_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace lrchain::python
