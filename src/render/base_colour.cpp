#include "render/base_colour.h"

namespace mirage {

gpu::Program baseColourProgram() {
  return gpu::Program::graphics("render/shaders/scene.vert", "render/shaders/base_colour.frag");
}

}  // namespace mirage
