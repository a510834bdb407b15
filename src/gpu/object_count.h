// Counting OpenGL objects, to prove that the viewer's method switches and the tools' repeated
// renders leak nothing: the handles mirage holds (gpu/handle.h) and, independently of them, the
// names GL itself reports as objects (glIsBuffer, glIsTexture, ...) up to the largest name seen.
#pragma once

#include <string>

namespace mirage::gpu {

struct ObjectCounts {
  long buffers = 0, textures = 0, framebuffers = 0, vertex_arrays = 0, programs = 0, shaders = 0,
       queries = 0;

  long total() const {
    return buffers + textures + framebuffers + vertex_arrays + programs + shaders + queries;
  }
  bool operator==(const ObjectCounts&) const = default;
  std::string text() const;  // "buffers 12, textures 30, ..."
};

// The handles alive now, by kind.
ObjectCounts liveHandles();
// The objects the current context reports for names 1..max(largest handle name, `at_least`),
// by kind (objects made by others, Dear ImGui's for one, included). Needs a current context.
ObjectCounts glObjects(unsigned at_least = 256);

}  // namespace mirage::gpu
