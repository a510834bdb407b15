#include "render/probe_lookup.h"

#include "core/check.h"
#include "shading/gpu_types.h"

namespace mirage {

ProbeLookup ProbeLookup::kindFor(const Scene& scene, bool box) {
  ProbeLookup lookup;
  lookup.box = box;
  lookup.blend = !scene.probes.empty();
  return lookup;
}

std::vector<std::string> ProbeLookup::defines() const {
  std::vector<std::string> out;
  if (box) out.push_back("PROBE_BOX 1");
  if (blend) out.push_back("PROBE_BLEND 1");
  return out;
}

void ProbeLookup::bind(const gpu::Program& program) const {
  MIRAGE_CHECK(probes != nullptr);
  probes->bind(MIRAGE_UNIT_METHOD);
  if (blend) {
    MIRAGE_CHECK(volumes != nullptr);
    volumes->bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_METHOD_SSBO);
    program.set("u_probe_count", volume_count);
    return;
  }
  if (!box) return;
  MIRAGE_CHECK(centres != nullptr);
  centres->bindBase(GL_SHADER_STORAGE_BUFFER, MIRAGE_BIND_METHOD_SSBO);
  program.set("u_box_min", proxy.lo);
  program.set("u_box_max", proxy.hi);
  program.set("u_proxy_sphere", sphere_proxy ? 1 : 0);
  program.set("u_sphere", vec4(proxy.center(), proxy.radius()));
}

}  // namespace mirage
