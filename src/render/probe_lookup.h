// The reflection probes of `envmap` / `envmap-box` as a pass looks them up: what that pass binds
// for render/shaders/probe_lookup.glsl. The method that keeps the probes fills one in; another
// pass that shades with them (`ssr`'s screen-space pass, for the pixels its screen cannot show)
// reaches it through Method::probeLookup, not through the keeper's folder.
#pragma once

#include <string>
#include <vector>

#include "core/bounds.h"
#include "gpu/buffer.h"
#include "gpu/program.h"
#include "render/probe_array.h"

namespace mirage {

struct ProbeLookup {
  const ProbeArray* probes = nullptr;    // one cube per reflector (layer = reflector id - 1)
  bool box = false;                      // looked up through the proxy (PROBE_BOX)
  bool sphere_proxy = false;             // the proxy is the box's circumscribed sphere
  Bounds3 proxy;                         // the box proxy: the room, grown to hold every centre
  const gpu::Buffer* centres = nullptr;  // vec4 per reflector: where its probe was captured

  // The defines a program that includes probe_lookup.glsl is compiled with.
  std::vector<std::string> defines() const;
  // Binds the probes (and the box's centres) to their units and sets `program`'s uniforms.
  void bind(const gpu::Program& program) const;
};

}  // namespace mirage
