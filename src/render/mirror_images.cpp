#include "render/mirror_images.h"

#include <algorithm>

#include "shading/gpu_types.h"

namespace mirage {

void drawMirrorImages(const GpuScene& gpu, std::span<const MirrorImage> images,
                      const gpu::Program& mirror_program, const gpu::Program& base_program,
                      int skip) {
  base_program.use();
  for (int i : gpu.scene().reflectorInstances()) {
    const bool with_image = std::any_of(images.begin(), images.end(),
                                        [&](const MirrorImage& m) { return m.mirror == i; });
    if (!with_image && i != skip) gpu.draw(i);
  }
  mirror_program.use();
  for (const MirrorImage& m : images) {
    m.image->color().bind(MIRAGE_UNIT_METHOD);
    gpu.draw(m.mirror);
  }
}

}  // namespace mirage
