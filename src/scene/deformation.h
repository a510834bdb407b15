// Procedural deformation of a reflector's mesh over time, for dynamic scenes: a ripple, a
// travelling wave from a source point that displaces every vertex along its rest normal,
//   h(p, t) = A · e^(-r/D) · sin(k r − ω t),  r = sqrt(|p − c|² + (λ/4)²),  k = 2π/λ, ω = k v,
// (r is softened by λ/4 so that the source is a smooth crest, not a cone tip). The deformed
// normal tilts against the height's gradient in the tangent plane, n' = normalize(n − ∇ₜh): exact
// for a flat surface (a height field), and smooth across the seams of a UV-mapped mesh, which
// recomputed face normals would not be. The GPU scene and the ray tracer both draw the mesh this
// produces on the CPU, so that every method and the reference see the same surface.
#pragma once

#include "scene/mesh.h"

namespace mirage {

struct Deformation {
  enum class Kind { kNone, kRipple };

  Kind kind = Kind::kNone;
  float amplitude = 0.0f;   // peak displacement, object units
  float wavelength = 1.0f;  // λ, crest to crest, object units (> 0)
  float speed = 0.5f;       // v, crests move outwards at this many object units per second
  float decay = 0.0f;       // D > 0: the amplitude falls off with distance; 0: no fall-off
  vec3 center{0.0f};        // c, the wave's source in object space

  bool active() const { return kind != Kind::kNone && amplitude != 0.0f; }
  // The surface repeats after λ / |v| seconds (0 when it stands still).
  float period() const;
  // The largest displacement anywhere: bounds grow by it.
  float maxDisplacement() const { return active() ? std::abs(amplitude) : 0.0f; }
  // h(p, t) and its gradient ∇h in object space.
  float height(const vec3& p, float time) const;
  vec3 gradient(const vec3& p, float time) const;
};

// `rest` deformed at `time` into `out` (positions, normals and tangents; uvs and triangles
// copied). `out` may be reused from call to call: its storage is kept.
void deformMesh(const Mesh& rest, const Deformation& deformation, float time, Mesh& out);

}  // namespace mirage
