#include "scene/deformation.h"

#include <cmath>

namespace mirage {

namespace {

struct Wave {
  float r;      // softened distance from the source
  vec3 dr;      // ∇r
  float phase;  // k r − ω t
  float envelope;
};

Wave waveAt(const Deformation& d, const vec3& p, float time) {
  const float soft = 0.25f * d.wavelength;
  const vec3 offset = p - d.center;
  Wave w;
  w.r = std::sqrt(glm::dot(offset, offset) + soft * soft);
  w.dr = offset / w.r;
  const float k = 2.0f * kPi / d.wavelength;
  w.phase = k * (w.r - d.speed * time);
  w.envelope = d.decay > 0.0f ? std::exp(-w.r / d.decay) : 1.0f;
  return w;
}

}  // namespace

float Deformation::period() const {
  return active() && speed != 0.0f ? wavelength / std::abs(speed) : 0.0f;
}

float Deformation::height(const vec3& p, float time) const {
  if (!active()) return 0.0f;
  const Wave w = waveAt(*this, p, time);
  return amplitude * w.envelope * std::sin(w.phase);
}

vec3 Deformation::gradient(const vec3& p, float time) const {
  if (!active()) return vec3(0.0f);
  const Wave w = waveAt(*this, p, time);
  const float k = 2.0f * kPi / wavelength;
  // d/dr [A e^(-r/D) sin(k r − ω t)]
  float dh = k * std::cos(w.phase);
  if (decay > 0.0f) dh -= std::sin(w.phase) / decay;
  return amplitude * w.envelope * dh * w.dr;
}

void deformMesh(const Mesh& rest, const Deformation& d, float time, Mesh& out) {
  out.name = rest.name;
  out.source = rest.source;
  out.uvs = rest.uvs;
  out.triangles = rest.triangles;
  out.positions.resize(rest.positions.size());
  out.normals.resize(rest.positions.size());
  const bool has_normals = rest.normals.size() == rest.positions.size();
  for (size_t i = 0; i < rest.positions.size(); ++i) {
    const vec3 p = rest.positions[i];
    const vec3 n = has_normals ? rest.normals[i] : vec3(0.0f, 1.0f, 0.0f);
    out.positions[i] = p + d.height(p, time) * n;
    const vec3 g = d.gradient(p, time);
    const vec3 tilted = n - (g - n * glm::dot(n, g));
    const float len = glm::length(tilted);
    out.normals[i] = len > 0.0f ? tilted / len : n;
  }
  if (!has_normals) out.computeNormals();
  out.tangents.resize(rest.tangents.size());
  for (size_t i = 0; i < rest.tangents.size(); ++i) {
    const vec3 n = out.normals[i];
    vec3 t = vec3(rest.tangents[i]);
    t -= n * glm::dot(n, t);
    const float len = glm::length(t);
    out.tangents[i] = vec4(len > 0.0f ? t / len : vec3(rest.tangents[i]), rest.tangents[i].w);
  }
}

}  // namespace mirage
