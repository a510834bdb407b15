#include "eval/temporal.h"

#include <cmath>

namespace mirage {

void TemporalError::add(const Image& method, const Image& reference, const IdImage& ids) {
  MIRAGE_CHECK(method.size() == reference.size() && reference.size() == ids.size());
  Image error(method.width(), method.height());
  for (size_t i = 0; i < error.pixelCount(); ++i)
    error.data()[i] = method.data()[i] - reference.data()[i];
  double change = std::nan("");
  if (!previous_error_.empty()) {
    MIRAGE_CHECK(previous_error_.size() == error.size());
    double sum = 0.0;
    size_t pixels = 0;
    for (size_t i = 0; i < error.pixelCount(); ++i) {
      if (ids.data()[i] == 0 || previous_ids_.data()[i] == 0) continue;
      const vec3 d = glm::abs(vec3(error.data()[i]) - vec3(previous_error_.data()[i]));
      sum += (double(d.x) + double(d.y) + double(d.z)) / 3.0;
      ++pixels;
    }
    if (pixels > 0) change = sum / double(pixels);
  }
  per_frame_.push_back(change);
  previous_error_ = std::move(error);
  previous_ids_ = ids;
}

double TemporalError::mean() const {
  double sum = 0.0;
  int n = 0;
  for (double v : per_frame_)
    if (!std::isnan(v)) sum += v, ++n;
  return n > 0 ? sum / n : std::nan("");
}

}  // namespace mirage
