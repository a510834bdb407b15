// The tests' main: GoogleTest's, with the worker threads joined before the process exits
// (app/worker_threads.h says why) and the uniform names of every program checked, whatever the
// build type (gpu/program.h).
#include <gtest/gtest.h>

#include "app/worker_threads.h"
#include "gpu/program.h"

int main(int argc, char** argv) {
  const mirage::app::WorkerThreadsJoined workers;
  mirage::gpu::setUniformChecks(true);
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
