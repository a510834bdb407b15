#include "render/probe_array.h"

#include <algorithm>

#include "render/gpu_scene.h"

namespace mirage {

ProbeArray::ProbeArray(int size, GLenum format) : size_(size), format_(format) {}

void ProbeArray::allocate(int count, bool mip) {
  count = std::max(count, 1);
  const int levels = mip ? gpu::Texture::fullMipLevels(size_) : 1;
  if (texture_.layers() == 6 * count && texture_.levels() == levels) return;
  texture_ = gpu::Texture::createCubeArray(format_, size_, count, levels);
  states_.reset(size_t(count));
}

std::vector<Drift> ProbeArray::drifts(const GpuScene& gpu, const std::vector<vec3>& centres,
                                      const std::vector<std::vector<int>>& shown) const {
  std::vector<Drift> out;
  for (size_t k = 0; k < centres.size(); ++k)
    out.push_back(states_.drift(gpu, int(k), centres[k], shown[k], size_));
  return out;
}

void ProbeArray::capture(const GpuScene& gpu, int k, const vec3& centre,
                         const std::vector<int>& shown, float near_plane, float far_plane,
                         const Draw& draw) {
  if (!cube_) cube_ = std::make_unique<CubeCapture>(size_);
  cube_->capture(texture_, k, centre, near_plane, far_plane,
                 [&](const View& view) { draw(k, view); });
  states_.captured(gpu, k, centre, shown);
  ++captures_;
  captured_since_finish_.push_back(k);
}

void ProbeArray::finish() {
  // The captured cubes' mip chains: all at once when most are new.
  const int cubes = texture_.layers() / 6;
  if (captured_since_finish_.size() * 2 > size_t(cubes))
    texture_.generateMipmaps();
  else
    for (int k : captured_since_finish_) texture_.generateMipmaps(6 * k, 6);
  captured_since_finish_.clear();
}

vec3 ProbeArray::centre(int k, const vec3& otherwise) const {
  const ProbeState& s = states_.state(k);
  return s.valid ? s.centre : otherwise;
}

int ProbeArray::update(const GpuScene& gpu, int count, bool mip, const std::vector<vec3>& centres,
                       const std::vector<std::vector<int>>& shown, const RecapturePolicy& policy,
                       float near_plane, float far_plane, const Draw& draw) {
  allocate(count, mip);
  const std::vector<Drift> drift = drifts(gpu, centres, shown);
  const std::vector<int> due = chooseRecaptures(drift, policy);
  for (int k : due)
    capture(gpu, k, centres[size_t(k)], shown[size_t(k)], near_plane, far_plane, draw);
  pending_ = int(chooseRecaptures(drift, {policy.angle_degrees, policy.texels, 0}).size()) -
             int(due.size());
  finish();
  nextFrame();
  return int(due.size());
}

int ProbeArray::updateAtReflectors(const GpuScene& gpu, bool mip, const std::vector<int>& own,
                                   const std::vector<int>& shown_from,
                                   const std::vector<int>& reflectors,
                                   const RecapturePolicy& policy, float radius, const Draw& draw) {
  std::vector<vec3> centres;
  std::vector<std::vector<int>> shown;
  for (int instance : own) {
    centres.push_back(gpu.instanceBounds(instance).center());
    shown.push_back(shownByProbe(shown_from, reflectors, instance));
  }
  return update(gpu, int(own.size()), mip, centres, shown, policy, 1e-3f * radius, 100.0f * radius,
                draw);
}

std::vector<int> shownByProbe(const std::vector<int>& diffuse, const std::vector<int>& reflectors,
                              int own) {
  std::vector<int> shown = diffuse;
  for (int r : reflectors)
    if (r != own) shown.push_back(r);
  return shown;
}

}  // namespace mirage
