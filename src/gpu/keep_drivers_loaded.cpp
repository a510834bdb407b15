#include "gpu/keep_drivers_loaded.h"

#include <cstring>

#include <dlfcn.h>
#include <link.h>

namespace mirage::gpu {

void keepDriversLoaded() {
#ifdef MIRAGE_SANITIZE
  dl_iterate_phdr(
      [](dl_phdr_info* info, size_t, void*) {
        const char* name = info->dlpi_name;
        if (name && (std::strstr(name, "/dri/") || std::strstr(name, "libgallium") ||
                     std::strstr(name, "libLLVM") || std::strstr(name, "_mesa") ||
                     std::strstr(name, "libGLX") || std::strstr(name, "libEGL"))) {
          // RTLD_NOLOAD: only a library already loaded; the handle is kept on purpose.
          dlopen(name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        }
        return 0;
      },
      nullptr);
#endif
}

}  // namespace mirage::gpu
