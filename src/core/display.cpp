#include "core/display.h"

#include <filesystem>

#include "core/choices.h"
#include "core/error.h"
#include "shading/tonemap.h"

namespace mirage {

Image toDisplay(const Image& linear, const DisplaySettings& settings) {
  Image out(linear.width(), linear.height());
  for (size_t i = 0; i < linear.pixelCount(); ++i)
    out.data()[i] = vec4(shading::display_transform(vec3(linear.data()[i]), settings.exposure,
                                                    int(settings.tonemap)),
                         1.0f);
  return out;
}

namespace {

constexpr Choice<ToneMap> kToneMaps[] = {
    {"clamp", ToneMap::kClamp}, {"reinhard", ToneMap::kReinhard}, {"aces", ToneMap::kAces}};

}  // namespace

ToneMap parseToneMap(const std::string& name) {
  if (const auto tonemap = findChoice<ToneMap>(kToneMaps, name)) return *tonemap;
  throwInput("--tonemap {}: unknown tone map (allowed: {})", name, choiceNames<ToneMap>(kToneMaps));
}

const char* toneMapName(ToneMap tonemap) {
  return choiceName<ToneMap>(kToneMaps, tonemap);
}

void writeImage(const std::string& path, const Image& linear, const DisplaySettings& settings) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".exr") {
    Image rgb = linear;
    for (vec4& p : rgb.pixels()) p.w = 1.0f;  // alpha holds distances: not for viewers
    writeExr(path, rgb);
  } else if (ext == ".png") {
    writePng(path, toDisplay(linear, settings));
  } else {
    throwInput("-o {}: unsupported image extension '{}' (allowed: .png, .exr)", path, ext);
  }
}

}  // namespace mirage
