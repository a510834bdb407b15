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
#include "scene/scene.h"

namespace mirage {

struct ProbeLookup {
  // One cube per reflector (layer = reflector id - 1), or with `blend` one per scene probe.
  const ProbeArray* probes = nullptr;
  bool box = false;                      // looked up through the proxy (PROBE_BOX)
  bool sphere_proxy = false;             // the proxy is the box's circumscribed sphere
  Bounds3 proxy;                         // the box proxy: the room, grown to hold every centre
  const gpu::Buffer* centres = nullptr;  // vec4 per reflector: where its probe was captured
  // A scene's own probes (scene/probes.h), blended by position (PROBE_BLEND): `volumes` holds a
  // shading::ProbeVolumeData per probe in blend order, each with its proxy; the fields above but
  // `probes` and `box` are unused then.
  bool blend = false;
  const gpu::Buffer* volumes = nullptr;
  int volume_count = 0;

  // The kind of lookup of a scene's reflection probes, through a box proxy or not: its own probes
  // blended when it gives some (Scene::probes), else one probe per reflector. What a program that
  // shades with `envmap` / `envmap-box`'s probes is compiled for (the fields but box and blend
  // are filled in once the probes are captured).
  static ProbeLookup kindFor(const Scene& scene, bool box);
  // The defines a program that includes probe_lookup.glsl is compiled with.
  std::vector<std::string> defines() const;
  // Binds the probes (and the box's centres) to their units and sets `program`'s uniforms.
  void bind(const gpu::Program& program) const;
};

// A box proxy for probes captured at the points `centres` bounds: the bounds of what they show,
// open (`open` away) on every side where those do not enclose the centres. A floor's box has no
// top, so that a ray leaving a reflector upwards meets the sky along its own direction, not the
// floor's plane lifted to the reflector's height; a room's box is the room.
Bounds3 openProxy(const Bounds3& shown, const Bounds3& centres, float open);

}  // namespace mirage
