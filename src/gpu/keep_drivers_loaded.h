// Sanitizer builds only: keeps the OpenGL driver's libraries loaded for the life of the process.
// Mesa keeps a little memory for its own lifetime (112 bytes under EGL, more under GLX) and
// drops the last pointer to it when eglTerminate/glfwTerminate unloads the driver, which
// LeakSanitizer then reports as a leak it cannot even attribute to a library. Kept loaded, that
// memory stays reachable: no suppression is needed, and every leak of mirage's is still reported.
#pragma once

namespace mirage::gpu {

// Marks every loaded driver library (Mesa's DRI/gallium drivers, GL/EGL vendor libraries, LLVM)
// RTLD_NODELETE. Does nothing outside a sanitizer build (MIRAGE_SANITIZE).
void keepDriversLoaded();

}  // namespace mirage::gpu
