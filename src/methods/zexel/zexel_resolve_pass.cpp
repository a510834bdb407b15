#include "methods/zexel/zexel_resolve_pass.h"

#include <string>

#include "methods/zexel/zexel_cpu_warper.h"
#include "methods/zexel/zexel_shared.h"

namespace mirage {

int ZexelResolvePass::strip(int width) const {
  if (!window_) return 1;
  const int group = MIRAGE_ZEXEL_RESOLVE_GROUP, longest = 16;
  const int groups = (width + group * longest - 1) / (group * longest);
  return (width + group * groups - 1) / (group * groups);
}

ZexelResolvePass::ZexelResolvePass(const ZexelSplatOptions& sizes)
    : window_(zexelSplatReach(sizes) == 1),
      resolve_(gpu::Program::compute(
          "methods/zexel/zexel_resolve.comp",
          {"ZEXEL_REACH " + std::to_string(zexelSplatReach(sizes)),
           std::string("ZEXEL_ALL_COVER ") + (zexelSplatsAllCover(sizes) ? "1" : "0")})) {}

void ZexelResolvePass::run(const ZexelSplatOptions& splats, ZexelWarpTarget& target) const {
  const ivec4 r = splats.rect;
  if (r.z <= r.x || r.w <= r.y) return;
  target.reserveResolved(r);
  target.bindTexels();
  target.bindResolvedImage();
  resolve_.set("u_rect", r);
  resolve_.set("u_margin", zexelCellMargin(splats));
  resolve_.set("u_tolerance", splats.tolerance);
  const int group = MIRAGE_ZEXEL_RESOLVE_GROUP, across = group * strip(r.z - r.x);
  if (window_) resolve_.set("u_strip", across / group);
  resolve_.use();
  glDispatchCompute(GLuint((r.z - r.x + across - 1) / across),
                    GLuint((r.w - r.y + group - 1) / group), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace mirage
