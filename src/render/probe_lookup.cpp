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

Bounds3 openProxy(const Bounds3& shown, const Bounds3& centres, float open) {
  Bounds3 proxy{centres.lo - vec3(open), centres.hi + vec3(open)};
  if (shown.empty()) return proxy;
  for (int a = 0; a < 3; ++a) {
    if (shown.lo[a] < centres.lo[a]) proxy.lo[a] = shown.lo[a];
    if (shown.hi[a] > centres.hi[a]) proxy.hi[a] = shown.hi[a];
  }
  return proxy;
}

}  // namespace mirage
