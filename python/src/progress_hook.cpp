// ProgressHook: throttled calls of a Python progress callback from a run without the GIL.
#include "progress_hook.hpp"

namespace py = pybind11;

namespace lrchain::python {

std::function<void(double)> ProgressHook::hook() {
  if (callback_.is_none()) return {};
  return [this](double fraction) { report(fraction); };
}

void ProgressHook::report(double fraction) {
  if (callback_.is_none()) return;
  const auto now = std::chrono::steady_clock::now();
  if (fraction < 1 && now - last_ < std::chrono::milliseconds(200)) return;
  last_ = now;
  py::gil_scoped_acquire gil;
  try {
    callback_(fraction);
  } catch (py::error_already_set& e) {  // a broken progress display must not end the run: drop it
    e.discard_as_unraisable("lrchain progress callback");
    callback_ = py::none();
  }
}

}  // namespace lrchain::python
