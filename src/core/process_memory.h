// The process's resident memory (RSS) and its allocator, for the soak checks of `mirage bench`
// and the viewer.
#pragma once

namespace mirage {

// Resident set size in MiB, from /proc/self/statm; 0 where that cannot be read.
double residentMiB();

// Which allocator serves malloc: "tbbmalloc" where the mirage binary is linked with TBB's
// malloc proxy (the default outside sanitizer builds; docs/reliability.md says why), else
// "glibc".
const char* processAllocator();

// Gives the allocator's cached free memory back to the system (malloc_trim, or tbbmalloc's
// clean-all-buffers), so that what stays resident afterwards is memory held.
void releaseFreeMemory();

}  // namespace mirage
