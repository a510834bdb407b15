// The process's resident memory (RSS), for the soak checks of `mirage bench` and the viewer.
#pragma once

namespace mirage {

// Resident set size in MiB, from /proc/self/statm; 0 where that cannot be read.
double residentMiB();

}  // namespace mirage
