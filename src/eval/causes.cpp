#include "eval/causes.h"

#include <vector>

#include "core/error.h"
#include "core/supersample.h"

namespace mirage {

const char* causeName(uint32_t label) {
  static const char* const kNames[] = {"none",      "environment",  "diffuse",     "self",
                                       "reflector", "beyond_order", "unclassified"};
  return label <= kUnclassified ? kNames[label] : "unknown";
}

vec3 causeColour(uint32_t label) {
  static const vec3 kColours[] = {
      {0.0f, 0.0f, 0.0f},    {0.35f, 0.7f, 1.0f},  // environment: sky blue
      {1.0f, 0.6f, 0.15f},                         // diffuse: orange
      {0.75f, 0.35f, 0.95f},                       // self: violet
      {0.3f, 0.85f, 0.35f},                        // reflector: green
      {0.75f, 0.75f, 0.75f},                       // beyond_order: light grey
      {1.0f, 0.15f, 0.15f},                        // unclassified: red
  };
  return label <= kUnclassified ? kColours[label] : vec3(1.0f, 0.0f, 1.0f);
}

PixelCauses classifyCauses(const IdImage& first_hits, int n, const IdImage& mask) {
  const ivec2 size = mask.size();
  if (n < 1 || first_hits.size() != size * n)
    throwRuntime("classifyCauses: first hits of {}x{} do not cover a {}x{} mask at {}x{}",
                 first_hits.width(), first_hits.height(), size.x, size.y, n, n);
  PixelCauses out{IdImage(size.x, size.y), IdImage(size.x, size.y), IdImage(size.x, size.y)};
  std::vector<uint32_t> block;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      if (mask(x, y) == 0) continue;
      block.clear();
      bool differ = false;
      const uint32_t first = first_hits(x * n, y * n);
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
          const uint32_t code = first_hits(x * n + i, y * n + j);
          differ = differ || code != first;
          if (code != 0) block.push_back(code);
        }
      out.mixed(x, y) = differ ? 1u : 0u;
      if (block.empty()) {
        out.label(x, y) = kUnclassified;
        continue;
      }
      const uint32_t best = mostFrequent(block);
      out.code(x, y) = best;
      out.label(x, y) = uint32_t(firstHitKind(best));
    }
  return out;
}

Image causeImage(const PixelCauses& causes, const Image& reference_display) {
  Image out(reference_display.width(), reference_display.height());
  for (int y = 0; y < out.height(); ++y)
    for (int x = 0; x < out.width(); ++x) {
      const uint32_t label = causes.label(x, y);
      if (label == 0) {
        const vec4 c = reference_display(x, y);
        const float grey = 0.25f * (0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z);
        out(x, y) = vec4(vec3(grey), 1.0f);
        continue;
      }
      const float shade = causes.mixed(x, y) ? 0.55f : 1.0f;
      out(x, y) = vec4(causeColour(label) * shade, 1.0f);
    }
  return out;
}

}  // namespace mirage
