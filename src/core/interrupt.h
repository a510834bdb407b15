// Ctrl-C and SIGTERM stop long work cleanly. The first signal only raises a flag, which the long
// loops (ray-traced tiles, frames of bench/render/compare, the viewer's loop) check and answer
// by throwing Interrupted: the stack unwinds, AtomicFile's destructors remove their temporary
// files, and nothing half-written is left behind. A second signal does not wait: it removes the
// temporary files still open and exits at once. Both exit with 128 + the signal's number.
#pragma once

#include "core/error.h"

namespace mirage {

class Interrupted : public Error {
 public:
  explicit Interrupted(int signal);
  int signal() const { return signal_; }

 private:
  int signal_;
};

// Installs the SIGINT and SIGTERM handlers (the `mirage` tool does this first thing).
void installInterruptHandlers();
// Whether a signal asked us to stop (relaxed load: safe in any thread, any loop).
bool interruptRequested();
// Throws Interrupted if a signal asked us to stop.
void checkInterrupt();
// Raises the flag as a signal would (tests).
void requestInterrupt(int signal);
void clearInterrupt();

// Temporary files a second signal removes before exiting (AtomicFile registers its own). At most
// a fixed number are tracked (signal handlers cannot allocate); the rest are left to AtomicFile's
// destructor.
void registerTemporaryFile(const char* path);
void unregisterTemporaryFile(const char* path);

}  // namespace mirage
