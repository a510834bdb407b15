// Sanitizer builds only: keeps the OpenGL driver's libraries loaded for the life of the process.
// Mesa allocates a little it never frees (112 bytes at eglTerminate, more under GLX); once the
// driver is unloaded LeakSanitizer can no longer say which library made the allocation, so the
// report could only be silenced wholesale. Kept loaded, the leak is named by its library and
// suppressed by that name alone (tests/lsan.supp), and every leak of ours is still reported.
#pragma once

namespace mirage::gpu {

// Marks every loaded driver library (Mesa's DRI/gallium drivers, GL/EGL vendor libraries, LLVM)
// RTLD_NODELETE. Does nothing outside a sanitizer build (MIRAGE_SANITIZE).
void keepDriversLoaded();

}  // namespace mirage::gpu
