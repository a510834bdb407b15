// Images in memory: linear RGBA float (what every method and the ray tracer produce) and
// single-channel integer images (reflector IDs). Row 0 is the top row.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/check.h"
#include "core/error.h"
#include "core/math.h"

namespace mirage {

template <typename T>
class Image2D {
 public:
  Image2D() = default;
  Image2D(int width, int height, T fill = T{}) : width_(width), height_(height) {
    if (width < 0 || height < 0) throwInput("image size {}x{} is negative", width, height);
    pixels_.assign(size_t(width) * size_t(height), fill);
  }

  int width() const { return width_; }
  int height() const { return height_; }
  ivec2 size() const { return {width_, height_}; }
  bool empty() const { return pixels_.empty(); }
  size_t pixelCount() const { return pixels_.size(); }

  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }
  // Pixel (x, y), (0, 0) the top left; checked in debug builds (the hot loops of every pass).
  T& operator()(int x, int y) {
    MIRAGE_DCHECK(contains(x, y));
    return pixels_[size_t(y) * size_t(width_) + size_t(x)];
  }
  const T& operator()(int x, int y) const {
    MIRAGE_DCHECK(contains(x, y));
    return pixels_[size_t(y) * size_t(width_) + size_t(x)];
  }
  T* data() { return pixels_.data(); }
  const T* data() const { return pixels_.data(); }
  std::vector<T>& pixels() { return pixels_; }
  const std::vector<T>& pixels() const { return pixels_; }

  // Reverses the row order (OpenGL reads back bottom row first).
  void flipVertically() {
    for (int y = 0; y < height_ / 2; ++y)
      for (int x = 0; x < width_; ++x) std::swap((*this)(x, y), (*this)(x, height_ - 1 - y));
  }

 private:
  int width_ = 0, height_ = 0;
  std::vector<T> pixels_;
};

using Image = Image2D<vec4>;        // linear RGBA radiance (or any float data)
using IdImage = Image2D<uint32_t>;  // reflector ID per pixel: 0 = not a reflector

// How 8-bit files are decoded: colour textures are sRGB, normal maps and masks are linear.
enum class Encoding { kSrgb, kLinear };

// Reads PNG/JPEG/TGA/BMP (stb), Radiance HDR (stb) or OpenEXR (any compression, DWAB included).
// 8-bit data is decoded with `encoding`; float formats are returned as stored.
Image readImage(const std::string& path, Encoding encoding = Encoding::kSrgb);
// The same from bytes already in memory; `name` is used in messages and for the format.
Image readImageFromMemory(const std::string& name, const void* data, size_t size,
                          Encoding encoding = Encoding::kSrgb);

// Writes an image whose values are already display-encoded in [0, 1] as an 8-bit RGBA PNG.
void writePng(const std::string& path, const Image& display, bool keep_alpha = false);
// Writes linear float data as a half-float RGBA OpenEXR file.
void writeExr(const std::string& path, const Image& linear);

// sRGB transfer functions (IEC 61966-2-1).
float srgbToLinear(float v);
float linearToSrgb(float v);

}  // namespace mirage
