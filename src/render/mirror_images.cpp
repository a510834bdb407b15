#include "render/mirror_images.h"

#include <algorithm>

#include "shading/gpu_types.h"

namespace mirage {

void drawMirrorImages(const GpuScene& gpu, std::span<const MirrorImage> images,
                      const gpu::Program& mirror_program, const gpu::Program& base_program,
                      int skip, const std::vector<int>* only) {
  base_program.use();
  for (int i : only ? *only : gpu.scene().reflectorInstances()) {
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

ivec4 screenRect(const View& view, const Bounds3& b) {
  const ivec2 size = view.size();
  vec2 lo(float(size.x), float(size.y)), hi(0.0f);
  for (int corner = 0; corner < 8; ++corner) {
    const vec3 x((corner & 1) ? b.hi.x : b.lo.x, (corner & 2) ? b.hi.y : b.lo.y,
                 (corner & 4) ? b.hi.z : b.lo.z);
    const vec3 p = view.project(x);  // top-left origin; z: eye depth
    if (!(p.z > 0.0f)) return ivec4(0, 0, size);
    const vec2 window(p.x, float(size.y) - p.y);
    lo = glm::min(lo, window);
    hi = glm::max(hi, window);
  }
  const ivec2 first = glm::clamp(ivec2(glm::floor(lo)) - 1, ivec2(0), size);
  const ivec2 last = glm::clamp(ivec2(glm::ceil(hi)) + 1, ivec2(0), size);
  return ivec4(first, last);
}

}  // namespace mirage
