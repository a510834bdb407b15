// The process's worker threads (TBB's: BVH builds, the CPU warper, parallel loops), joined
// before the process exits.
#pragma once

#include <tbb/global_control.h>

namespace mirage::app {

// Made first thing in main (the tool's and the tests'); its destructor, as main returns, waits
// until every TBB worker thread has ended. Left to themselves the workers end during exit(),
// after main, at the same time as LeakSanitizer's check of the process (sanitizer builds), which
// then reads the stacks of threads that are tearing them down. Joined here, no thread is ending
// when the check runs (the check's crashes in runs that leaked nothing had another cause:
// sanitizer_defaults.cpp). Where TBB cannot wait (a thread pool still in use), it says so in a
// debug line and the workers end as before.
class WorkerThreadsJoined {
 public:
  WorkerThreadsJoined();
  ~WorkerThreadsJoined();
  WorkerThreadsJoined(const WorkerThreadsJoined&) = delete;
  WorkerThreadsJoined& operator=(const WorkerThreadsJoined&) = delete;

 private:
  tbb::task_scheduler_handle handle_;
};

}  // namespace mirage::app
