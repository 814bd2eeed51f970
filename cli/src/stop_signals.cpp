// SIGINT/SIGTERM handling of long runs (stop_signals.hpp): sigaction, lock-free atomics only.
#include "stop_signals.hpp"

#include <signal.h>

namespace lrchain::cli {

namespace {

std::atomic<bool> g_stop{false};
std::atomic<int> g_signal{0};
int g_depth = 0;  // StopSignals alive (the CLI's main thread only)
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free);

void set_action(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
}

// First signal: ask the run to stop; the handlers go back to the default, so that a second
// SIGINT or SIGTERM ends the process at once (sigaction is async-signal-safe).
extern "C" void on_stop_signal(int signal_number) {
  g_signal.store(signal_number);
  g_stop.store(true);
  set_action(SIG_DFL);
}

}  // namespace

StopSignals::StopSignals() {
  if (g_depth++ > 0) return;
  g_stop.store(false);
  g_signal.store(0);
  set_action(on_stop_signal);
}

StopSignals::~StopSignals() {
  if (--g_depth == 0) set_action(SIG_DFL);
}

const std::atomic<bool>* StopSignals::flag() { return &g_stop; }

int StopSignals::received() { return g_signal.load(); }

const char* StopSignals::name(int signal_number) { return signal_number == SIGTERM ? "SIGTERM" : "SIGINT"; }

}  // namespace lrchain::cli
