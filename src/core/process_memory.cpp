#include "core/process_memory.h"

#include <cstdio>

#include <dlfcn.h>
#include <malloc.h>
#include <unistd.h>

#include <tbb/scalable_allocator.h>  // the command codes only: the call is looked up

namespace mirage {

double residentMiB() {
  FILE* f = std::fopen("/proc/self/statm", "r");
  if (!f) return 0.0;
  unsigned long size = 0, resident = 0;
  const int read = std::fscanf(f, "%lu %lu", &size, &resident);
  std::fclose(f);
  if (read != 2) return 0.0;
  return double(resident) * double(sysconf(_SC_PAGESIZE)) / (1024.0 * 1024.0);
}

namespace {
// Looked up at run time: the proxy is a link option of the mirage binary only, and libtbb may
// load libtbbmalloc for its own use without it replacing malloc, so the proxy's own marker
// symbol is what tells.
bool tbbmallocProxyLoaded() {
  static const bool loaded = dlsym(RTLD_DEFAULT, "__TBB_malloc_proxy") != nullptr;
  return loaded;
}
}  // namespace

const char* processAllocator() {
  return tbbmallocProxyLoaded() ? "tbbmalloc" : "glibc";
}

void releaseFreeMemory() {
  if (tbbmallocProxyLoaded()) {
    using Command = int (*)(int, void*);
    if (auto command =
            reinterpret_cast<Command>(dlsym(RTLD_DEFAULT, "scalable_allocation_command")))
      command(TBBMALLOC_CLEAN_ALL_BUFFERS, nullptr);
    return;
  }
  malloc_trim(0);
}

}  // namespace mirage
