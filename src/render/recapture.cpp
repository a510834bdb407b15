#include "render/recapture.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "render/gpu_scene.h"

namespace mirage {

namespace {

// Drift relative to the tolerances: > 1 is beyond them; infinite for an unmeasured change.
float relativeDrift(const Drift& d, const RecapturePolicy& policy) {
  if (d.unmeasured) return kInfinity;
  auto ratio = [](float value, float tolerance) {
    if (value <= 0.0f) return 0.0f;
    return tolerance > 0.0f ? value / tolerance : kInfinity;
  };
  return std::max(ratio(d.angle, glm::radians(policy.angle_degrees)),
                  ratio(d.texels, policy.texels));
}

// Distance from `p` to the box, or from inside it to its nearest face.
float distanceToBox(const vec3& p, const Bounds3& box) {
  if (box.empty()) return 0.0f;
  if (!box.contains(p)) return glm::length(glm::max(glm::max(box.lo - p, p - box.hi), vec3(0.0f)));
  const vec3 inside = glm::min(p - box.lo, box.hi - p);
  return std::min({inside.x, inside.y, inside.z});
}

}  // namespace

std::vector<int> chooseRecaptures(const std::vector<Drift>& drift, const RecapturePolicy& policy) {
  std::vector<int> must, beyond;
  std::vector<float> rel(drift.size(), 0.0f);
  for (size_t i = 0; i < drift.size(); ++i) {
    if (drift[i].invalid) {
      must.push_back(int(i));
      continue;
    }
    rel[i] = relativeDrift(drift[i], policy);
    if (rel[i] > 1.0f) beyond.push_back(int(i));
  }
  std::stable_sort(beyond.begin(), beyond.end(), [&](int a, int b) {
    if (rel[size_t(a)] != rel[size_t(b)]) return rel[size_t(a)] > rel[size_t(b)];
    return drift[size_t(a)].age > drift[size_t(b)].age;
  });
  if (policy.budget > 0 && beyond.size() > size_t(policy.budget))
    beyond.resize(size_t(policy.budget));
  must.insert(must.end(), beyond.begin(), beyond.end());
  return must;
}

float motionAngle(const Bounds3& local, const mat4& before, const mat4& now,
                  const vec3& viewer_before, const vec3& viewer_now, const Bounds3& world) {
  if (local.empty()) return 0.0f;
  float moved = 0.0f;
  for (int i = 0; i < 8; ++i) {
    const vec3 c((i & 1) ? local.hi.x : local.lo.x, (i & 2) ? local.hi.y : local.lo.y,
                 (i & 4) ? local.hi.z : local.lo.z);
    const vec3 d =
        (transformPoint(now, c) - viewer_now) - (transformPoint(before, c) - viewer_before);
    moved = std::max(moved, glm::length(d));
  }
  if (moved == 0.0f) return 0.0f;
  // A viewer on the object's surface sees it move by up to a half turn.
  const float distance = distanceToBox(viewer_now, world);
  return distance > 0.0f ? std::min(std::atan2(moved, distance), kPi) : kPi;
}

Drift ProbeRecapture::drift(const GpuScene& gpu, int p, const vec3& centre,
                            const std::vector<int>& shown, int face_size) const {
  const ProbeState& s = states_[size_t(p)];
  Drift d;
  d.age = frame_ - s.frame;
  if (!s.valid || s.matrices.size() != shown.size()) {
    d.invalid = true;
    return d;
  }
  const Light& light = gpu.light();
  d.unmeasured = light.color != s.light_color || light.ambient != s.ambient;
  if (light.direction != s.light_direction)
    d.angle = std::acos(std::clamp(glm::dot(light.direction, s.light_direction), -1.0f, 1.0f));
  const Scene& scene = gpu.scene();
  for (size_t k = 0; k < shown.size(); ++k) {
    const int i = shown[k];
    if (gpu.shapeVersion(i) != s.shapes[k]) d.unmeasured = true;
    const mat4& now = gpu.instanceMatrix(i);
    if (now == s.matrices[k] && centre == s.centre) continue;
    d.angle = std::max(d.angle, motionAngle(scene.localBounds(i), s.matrices[k], now, s.centre,
                                            centre, gpu.instanceBounds(i)));
  }
  // One texel of a cube face spans about (pi / 2) / face_size radians.
  d.texels = d.angle * float(face_size) / (0.5f * kPi);
  return d;
}

void ProbeRecapture::captured(const GpuScene& gpu, int p, const vec3& centre,
                              const std::vector<int>& shown) {
  ProbeState& s = states_[size_t(p)];
  s.valid = true;
  s.centre = centre;
  s.matrices.clear();
  s.shapes.clear();
  for (int i : shown) {
    s.matrices.push_back(gpu.instanceMatrix(i));
    s.shapes.push_back(gpu.shapeVersion(i));
  }
  const Light& light = gpu.light();
  s.light_direction = light.direction;
  s.light_color = light.color;
  s.ambient = light.ambient;
  s.frame = frame_;
}

}  // namespace mirage
