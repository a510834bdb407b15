// The distant environment as a cube map in memory: built from an equirectangular image or the
// procedural sky, sampled on the CPU exactly as the GPU samples the same texels (bilinear,
// level 0, seamless across faces), and uploaded unchanged to the GPU.
#pragma once

#include <array>
#include <vector>

#include "core/image.h"
#include "core/math.h"

namespace mirage {

struct Scene;
struct Light;
struct EnvironmentDesc;

class EnvironmentMap {
 public:
  EnvironmentMap() = default;

  // The procedural sky (shading/sky.h) with the sun in the light's direction.
  static EnvironmentMap sky(const Light& light, int face_size);
  // An equirectangular (latitude-longitude) image, rotated about +Y by `rotation_degrees`.
  static EnvironmentMap equirect(const Image& image, int face_size, float rotation_degrees);
  // The scene's environment: its image (loaded here) or the sky; intensity and clamp applied.
  static EnvironmentMap forScene(const Scene& scene);

  int faceSize() const { return size_; }
  const std::vector<vec4>& face(int f) const { return faces_[size_t(f)]; }

  // Radiance in direction `d` (need not be unit): bilinear on level 0, seamless across faces.
  vec3 sample(const vec3& d) const;
  // The texel (face, x, y) value.
  vec3 texel(int face, int x, int y) const {
    return vec3(faces_[size_t(face)][size_t(y * size_ + x)]);
  }

 private:
  template <typename F>
  static EnvironmentMap fromFunction(int face_size, F radiance);
  // Rounds to half precision, the precision of the GPU's RGBA16F copy, and applies the scale.
  void finish(float intensity, float clamp);

  int size_ = 0;
  std::array<std::vector<vec4>, 6> faces_;
};

// Equirectangular mapping: direction -> (u, v) in [0, 1]^2, v = 0 at the zenith.
vec2 equirectUv(const vec3& unit_direction);

}  // namespace mirage
