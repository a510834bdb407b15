#include "eval/heatmap.h"

#include <algorithm>
#include <array>

#include "shading/heatmap.h"

namespace mirage {

vec3 magma(float t) {
  return shading::magma(t);
}

Image2D<float> absoluteError(const Image& a, const Image& b) {
  Image2D<float> e(a.width(), a.height());
  for (size_t i = 0; i < e.pixelCount(); ++i) {
    e.data()[i] = shading::display_error(vec3(a.data()[i]), vec3(b.data()[i]));
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
