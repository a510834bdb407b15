#include "app/worker_threads.h"

#include <new>

#include <spdlog/spdlog.h>

namespace mirage::app {

WorkerThreadsJoined::WorkerThreadsJoined() : handle_(tbb::attach{}) {}

WorkerThreadsJoined::~WorkerThreadsJoined() {
  if (!tbb::finalize(handle_, std::nothrow))
    spdlog::debug("TBB's worker threads could not be joined before exit");
}

}  // namespace mirage::app
