#include "core/interrupt.h"

#include <atomic>
#include <csignal>
#include <cstring>

#include <unistd.h>

namespace mirage {

namespace {

std::atomic<bool> g_requested{false};
std::atomic<int> g_signal{0};

// Slots for temporary paths: a handler may only read them, so each is a fixed buffer claimed by
// a compare-and-swap on its flag. 0: free, 1: being written, 2: holds a path.
constexpr int kSlots = 64;
constexpr size_t kPathMax = 4096;
struct Slot {
  std::atomic<int> state{0};
  char path[kPathMax];
};
Slot g_slots[kSlots];

void onSignal(int sig) {
  if (g_requested.load()) {
    // Second signal: the user does not want to wait. unlink and _exit are async-signal-safe.
    for (Slot& s : g_slots)
      if (s.state.load() == 2) ::unlink(s.path);
    ::_exit(128 + sig);
  }
  g_signal.store(sig);  // before the flag: whoever sees the flag sees which signal it was
  g_requested.store(true);
}

}  // namespace

Interrupted::Interrupted(int signal)
    : Error(ExitCode(128 + signal),
            fmt::format("interrupted by {}: stopped cleanly, no file left half-written",
                        signal == SIGINT    ? "SIGINT (Ctrl-C)"
                        : signal == SIGTERM ? "SIGTERM"
                                            : "a signal")),
      signal_(signal) {}

void installInterruptHandlers() {
  struct sigaction action {};
  action.sa_handler = &onSignal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

bool interruptRequested() {
  return g_requested.load(std::memory_order_relaxed);
}

void checkInterrupt() {
  if (interruptRequested()) throw Interrupted(g_signal.load() ? g_signal.load() : SIGINT);
}

void requestInterrupt(int signal) {
  g_signal.store(signal);
  g_requested.store(true);
}

void clearInterrupt() {
  g_requested.store(false);
  g_signal.store(0);
}

void registerTemporaryFile(const char* path) {
  if (std::strlen(path) >= kPathMax) return;
  for (Slot& s : g_slots) {
    int expected = 0;
    if (s.state.compare_exchange_strong(expected, 1)) {
      std::strcpy(s.path, path);
      s.state.store(2);
      return;
    }
  }
}

void unregisterTemporaryFile(const char* path) {
  for (Slot& s : g_slots) {
    int expected = 2;
    if (s.state.load() == 2 && std::strcmp(s.path, path) == 0 &&
        s.state.compare_exchange_strong(expected, 1)) {
      s.path[0] = '\0';
      s.state.store(0);
      return;
    }
  }
}

}  // namespace mirage
