#include "eval/heatmap.h"

#include <algorithm>
#include <array>

namespace mirage {

vec3 magma(float t) {
  // Nine control points of matplotlib's magma, interpolated linearly.
  static const std::array<vec3, 9> kStops = {
      vec3(0.001f, 0.000f, 0.014f), vec3(0.110f, 0.066f, 0.296f), vec3(0.316f, 0.071f, 0.485f),
      vec3(0.512f, 0.128f, 0.507f), vec3(0.716f, 0.215f, 0.475f), vec3(0.904f, 0.315f, 0.384f),
      vec3(0.988f, 0.535f, 0.382f), vec3(0.996f, 0.780f, 0.520f), vec3(0.987f, 0.991f, 0.750f)};
  t = std::clamp(t, 0.0f, 1.0f) * float(kStops.size() - 1);
  size_t i = std::min(size_t(t), kStops.size() - 2);
  return glm::mix(kStops[i], kStops[i + 1], t - float(i));
}

Image2D<float> absoluteError(const Image& a, const Image& b) {
  Image2D<float> e(a.width(), a.height());
  for (size_t i = 0; i < e.pixelCount(); ++i) {
    vec3 d = glm::abs(vec3(a.data()[i]) - vec3(b.data()[i]));
    e.data()[i] = (d.x + d.y + d.z) / 3.0f;
  }
  return e;
}

Image heatmap(const Image2D<float>& error, float max_error) {
  Image out(error.width(), error.height());
  for (size_t i = 0; i < error.pixelCount(); ++i)
    out.data()[i] = vec4(magma(error.data()[i] / max_error), 1.0f);
  return out;
}

}  // namespace mirage
