// The tests' main: GoogleTest's, with the worker threads joined before the process exits
// (app/worker_threads.h says why).
#include <gtest/gtest.h>

#include "app/worker_threads.h"

int main(int argc, char** argv) {
  const mirage::app::WorkerThreadsJoined workers;
  testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
