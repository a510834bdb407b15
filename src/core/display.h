// The output transform of the shading model (docs/architecture.md, "One shading model":
// exposure, tone map, sRGB) applied to whole images, with the per-pixel function of
// shading/tonemap.h that a display shader would run.
#pragma once

#include <string>

#include "core/image.h"

namespace mirage {

enum class ToneMap { kClamp = 0, kReinhard = 1, kAces = 2 };

struct DisplaySettings {
  float exposure = 1.0f;
  ToneMap tonemap = ToneMap::kAces;
};

// Linear radiance to display-encoded values in [0, 1] (alpha set to 1).
Image toDisplay(const Image& linear, const DisplaySettings& settings);

// "clamp" | "reinhard" | "aces"; throws InputError listing the names.
ToneMap parseToneMap(const std::string& name);
const char* toneMapName(ToneMap tonemap);

// Writes a linear image: .exr keeps the linear floats, .png gets the display transform.
// Any other extension is an InputError naming the allowed ones.
void writeImage(const std::string& path, const Image& linear, const DisplaySettings& settings);

}  // namespace mirage
