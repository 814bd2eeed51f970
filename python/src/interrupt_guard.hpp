#pragma once
// Ctrl-C during a long computation that runs without the GIL: while a guard lives, SIGINT sets the
// library's stop flag (RunControl::stop, ContinuationOptions::stop) and is passed on to Python's
// own handler, so the computation ends at its next check and KeyboardInterrupt follows.
#include <atomic>
#include <csignal>
#include <optional>
#include <utility>

#include <pybind11/pybind11.h>

#include "lrchain/errors.hpp"

namespace lrchain::python {

class InterruptGuard {
 public:
  // With the GIL held. Installs the handler only on the main thread (where Python handles signals)
  // and only where SIGINT is not ignored; nested guards share the outermost one's handler.
  InterruptGuard();
  ~InterruptGuard();  // restores the previous handler
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  // The flag the library polls.
  const std::atomic<bool>* flag() const;
  bool interrupted() const;
  // With the GIL held: if SIGINT arrived, restores the handler, runs Python's signal handlers and
  // throws pybind11::error_already_set (KeyboardInterrupt unless a handler raised otherwise).
  void raise_if_interrupted();

  // Runs f() without the GIL, then raises KeyboardInterrupt if SIGINT arrived (also when f threw
  // lrchain::Interrupted); returns f's result otherwise.
  template <class F>
  auto run(F&& f) {
    std::optional<decltype(f())> result;
    try {
      pybind11::gil_scoped_release release;
      result.emplace(f());
    } catch (const Interrupted&) {
      raise_if_interrupted();
      throw;
    }
    raise_if_interrupted();
    return std::move(*result);
  }

 private:
  void restore();
  bool installed_ = false;
};

}  // namespace lrchain::python
