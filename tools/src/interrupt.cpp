#include "interrupt.hpp"

#include <csignal>

namespace lacrima::cli {

namespace {

// Only lock-free atomics may be touched from a signal handler.
static_assert(std::atomic<bool>::is_always_lock_free);
std::atomic<bool> gStop{false};
std::atomic<bool> gAbandon{false};

void setHandler(int signal, void (*handler)(int)) {
  struct sigaction action = {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  // Restart interrupted system calls: a signal must not make an EXR write fail half-way.
  action.sa_flags = SA_RESTART;
  sigaction(signal, &action, nullptr);
}

extern "C" void onInterrupt(int signal) {
  if (!gStop.exchange(true)) return;
  gAbandon.store(true);
  setHandler(signal, SIG_DFL);  // the next one terminates (sigaction is async-signal-safe)
}

}  // namespace

void installInterruptHandlers() {
  setHandler(SIGINT, onInterrupt);
  setHandler(SIGTERM, onInterrupt);
}

bool stopRequested() { return gStop.load(); }
const std::atomic<bool>& abandonRequested() { return gAbandon; }

}  // namespace lacrima::cli
