// SIGINT -> the library's stop flag, chained to Python's handler (interrupt_guard.hpp).
#include "interrupt_guard.hpp"

#include <pybind11/pybind11.h>

namespace py = pybind11;

namespace lrchain::python {

namespace {
// Process-wide, as signal dispositions are; changed only with the GIL held.
std::atomic<bool> stop_flag{false};
struct sigaction previous_action;
int depth = 0;  // guards alive that installed the handler

extern "C" void on_sigint(int signal_number, siginfo_t* info, void* context) {
  stop_flag.store(true, std::memory_order_relaxed);
  if (previous_action.sa_flags & SA_SIGINFO) {
    if (previous_action.sa_sigaction) previous_action.sa_sigaction(signal_number, info, context);
  } else if (previous_action.sa_handler != SIG_DFL && previous_action.sa_handler != SIG_IGN) {
    previous_action.sa_handler(signal_number);  // Python's: marks the signal for its handler
  }
}

bool on_main_thread() {
  const py::object main = py::module_::import("threading").attr("main_thread")();
  return main.attr("ident").cast<unsigned long>() == PyThread_get_thread_ident();
}
}  // namespace

InterruptGuard::InterruptGuard() {
  if (depth > 0) {
    ++depth;
    installed_ = true;
    return;
  }
  if (!on_main_thread()) return;
  struct sigaction current;
  if (sigaction(SIGINT, nullptr, &current) != 0 || (!(current.sa_flags & SA_SIGINFO) && current.sa_handler == SIG_IGN))
    return;
  struct sigaction action {};
  action.sa_sigaction = on_sigint;
  action.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigemptyset(&action.sa_mask);
  stop_flag.store(false);
  if (sigaction(SIGINT, &action, &previous_action) != 0) return;
  depth = 1;
  installed_ = true;
}

void InterruptGuard::restore() {
  if (!installed_) return;
  installed_ = false;
  if (--depth == 0) sigaction(SIGINT, &previous_action, nullptr);
}

InterruptGuard::~InterruptGuard() { restore(); }

const std::atomic<bool>* InterruptGuard::flag() const { return &stop_flag; }

bool InterruptGuard::interrupted() const { return installed_ && stop_flag.load(std::memory_order_relaxed); }

void InterruptGuard::raise_if_interrupted() {
  if (!interrupted()) return;
  const bool outermost = depth == 1;
  restore();
  if (outermost) stop_flag.store(false);
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
  PyErr_SetString(PyExc_KeyboardInterrupt, "interrupted by SIGINT");
  throw py::error_already_set();
}

}  // namespace lrchain::python
