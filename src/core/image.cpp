#include "core/image.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <filesystem>
#include <memory>

#include <ImfArray.h>
#include <ImfIO.h>
#include <ImfRgbaFile.h>
#include <stb_image.h>
#include <stb_image_write.h>

#include <spdlog/spdlog.h>

#include "core/atomic_file.h"
#include "core/image_header.h"
#include "core/memory_cap.h"
#include "core/radiance_check.h"

namespace mirage {

namespace {

// Refuse images whose header claims more than this, before allocating anything.
constexpr int64_t kMaxImageSide = 32768;
constexpr int64_t kMaxImagePixels = int64_t(1) << 27;  // 134M pixels = 2 GiB of RGBA float
// What decoding costs per pixel at its peak: the decoder's buffer (OpenEXR's half RGBA, 8 bytes;
// stb's float or 16-bit RGBA and its row buffers, up to 16) plus mirage's float RGBA (16).
constexpr uint64_t kExrBytesPerPixel = 8 + 16;
constexpr uint64_t kStbBytesPerPixel = 16 + 16;

void checkImageSize(const std::string& name, int64_t w, int64_t h, uint64_t bytes_per_pixel) {
  if (w <= 0 || h <= 0 || w > kMaxImageSide || h > kMaxImageSide || w * h > kMaxImagePixels)
    throwInput(
        "{}: image size {}x{} is outside the supported range (1..{} per side, at most {} "
        "pixels)",
        name, w, h, kMaxImageSide, kMaxImagePixels);
  checkAllocation(name, fmt::format("decoding its {}x{} pixels", w, h),
                  uint64_t(w) * uint64_t(h) * bytes_per_pixel);
}

// Float images may hold NaN and infinities, which would spread through every filter and metric
// they touch: NaN and -Inf become 0, +Inf the largest half float (65504), with one warning.
void sanitizeFloatPixels(const std::string& name, Image& image) {
  size_t replaced = 0;
  for (vec4& p : image.pixels())
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(p[c])) {
        p[c] = p[c] > 0.0f ? 65504.0f : 0.0f;
        ++replaced;
      }
  if (replaced > 0)
    spdlog::warn(
        "{}: {} non-finite channel values (NaN or infinite) replaced: NaN and -Inf by 0, "
        "+Inf by 65504",
        name, replaced);
}

const std::array<float, 256>& srgbTable() {
  static const std::array<float, 256> table = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) t[size_t(i)] = srgbToLinear(float(i) / 255.0f);
    return t;
  }();
  return table;
}

// An OpenEXR input stream over bytes in memory.
class MemoryStream : public Imf::IStream {
 public:
  MemoryStream(const std::string& name, const char* data, size_t size)
      : Imf::IStream(name.c_str()), data_(data), size_(size) {}
  bool read(char c[], int n) override {
    if (n < 0 || pos_ + size_t(n) > size_) throw std::runtime_error("unexpected end of file");
    std::memcpy(c, data_ + pos_, size_t(n));
    pos_ += size_t(n);
    return pos_ < size_;
  }
  uint64_t tellg() override { return pos_; }
  void seekg(uint64_t pos) override { pos_ = size_t(std::min<uint64_t>(pos, size_)); }

 private:
  const char* data_;
  size_t size_;
  size_t pos_ = 0;
};

Image readExr(const std::string& name, Imf::IStream& stream) {
  try {
    Imf::RgbaInputFile file(stream);
    Imath::Box2i window = file.dataWindow();
    int64_t w = int64_t(window.max.x) - window.min.x + 1;
    int64_t h = int64_t(window.max.y) - window.min.y + 1;
    checkImageSize(name, w, h, kExrBytesPerPixel);
    Imf::Array2D<Imf::Rgba> pixels(h, w);
    file.setFrameBuffer(&pixels[0][0] - window.min.x - window.min.y * w, 1, size_t(w));
    file.readPixels(window.min.y, window.max.y);
    Image image{int(w), int(h)};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Imf::Rgba& p = pixels[y][x];
        image(x, y) = vec4(float(p.r), float(p.g), float(p.b), float(p.a));
      }
    sanitizeFloatPixels(name, image);
    return image;
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throwInput("{}: not a readable OpenEXR file ({})", name, e.what());
  }
}

Image fromStb(const std::string& name, void* data, int w, int h, bool is_float, Encoding encoding) {
  if (!data) throwInput("{}: cannot decode image ({})", name, stbi_failure_reason());
  Image image(w, h);
  if (is_float) {
    const float* f = static_cast<const float*>(data);
    for (size_t i = 0; i < image.pixelCount(); ++i)
      image.data()[i] = vec4(f[4 * i], f[4 * i + 1], f[4 * i + 2], f[4 * i + 3]);
    sanitizeFloatPixels(name, image);
  } else {
    const unsigned char* b = static_cast<const unsigned char*>(data);
    const auto& table = srgbTable();
    for (size_t i = 0; i < image.pixelCount(); ++i) {
      vec4 v;
      for (int c = 0; c < 3; ++c)
        v[c] = encoding == Encoding::kSrgb ? table[b[4 * i + size_t(c)]]
                                           : b[4 * i + size_t(c)] / 255.0f;
      v.w = b[4 * i + 3] / 255.0f;  // alpha is always linear
      image.data()[i] = v;
    }
  }
  stbi_image_free(data);
  return image;
}

}  // namespace

float srgbToLinear(float v) {
  return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float v) {
  v = std::clamp(v, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

Image readImageFromMemory(const std::string& name, const void* data, size_t size,
                          Encoding encoding) {
  if (size == 0) throwInput("{}: empty image file", name);
  const char* bytes = static_cast<const char*>(data);
  const auto* header = static_cast<const unsigned char*>(data);
  if (size >= 4 && std::memcmp(bytes, "\x76\x2f\x31\x01", 4) == 0) {
    // Before OpenEXR reads the header and its offset tables, which an absurd data window makes
    // fail with only "unexpected end of file".
    if (auto claimed = claimedExrSize(header, size))
      checkImageSize(name, claimed->width, claimed->height, kExrBytesPerPixel);
    MemoryStream stream(name, bytes, size);
    return readExr(name, stream);
  }
  if (size > size_t(std::numeric_limits<int>::max())) throwInput("{}: file too large", name);
  // stb refuses a PNG larger than 2^30 bytes of pixels as "unknown image type": say why.
  if (auto claimed = claimedPngSize(header, size))
    checkImageSize(name, claimed->width, claimed->height, kStbBytesPerPixel);
  int w = 0, h = 0, channels = 0;
  auto* buffer = reinterpret_cast<const stbi_uc*>(data);
  if (!stbi_info_from_memory(buffer, int(size), &w, &h, &channels))
    throwInput("{}: not a readable image ({}); supported: PNG, JPEG, TGA, BMP, HDR, EXR", name,
               stbi_failure_reason());
  checkImageSize(name, w, h, kStbBytesPerPixel);
  if (stbi_is_hdr_from_memory(buffer, int(size))) {
    checkRadianceScanlines(name, buffer, size);
    float* f = stbi_loadf_from_memory(buffer, int(size), &w, &h, &channels, 4);
    return fromStb(name, f, w, h, true, encoding);
  }
  stbi_uc* b = stbi_load_from_memory(buffer, int(size), &w, &h, &channels, 4);
  return fromStb(name, b, w, h, false, encoding);
}

Image readImage(const std::string& path, Encoding encoding) {
  std::string bytes = readFile(path);
  return readImageFromMemory(path, bytes.data(), bytes.size(), encoding);
}

void writePng(const std::string& path, const Image& display, bool keep_alpha) {
  if (display.empty()) throwRuntime("cannot write '{}': empty image", path);
  std::vector<unsigned char> bytes(display.pixelCount() * 4);
  for (size_t i = 0; i < display.pixelCount(); ++i) {
    vec4 p = glm::clamp(display.data()[i], 0.0f, 1.0f);
    for (int c = 0; c < 4; ++c)
      bytes[4 * i + size_t(c)] = (unsigned char)std::lround(p[c] * 255.0f);
    if (!keep_alpha) bytes[4 * i + 3] = 255;
  }
  AtomicFile file(path);
  if (!stbi_write_png(file.tempPath().c_str(), display.width(), display.height(), 4, bytes.data(),
                      display.width() * 4))
    throwRuntime("cannot write '{}'", path);
  file.commit();
}

void writeExr(const std::string& path, const Image& linear) {
  if (linear.empty()) throwRuntime("cannot write '{}': empty image", path);
  std::vector<Imf::Rgba> pixels(linear.pixelCount());
  for (size_t i = 0; i < linear.pixelCount(); ++i) {
    const vec4& p = linear.data()[i];
    pixels[i] = Imf::Rgba(p.x, p.y, p.z, p.w);
  }
  AtomicFile file(path);
  try {
    Imf::RgbaOutputFile out(file.tempPath().c_str(), linear.width(), linear.height(),
                            Imf::WRITE_RGBA, 1.0f, Imath::V2f(0, 0), 1.0f, Imf::INCREASING_Y,
                            Imf::ZIP_COMPRESSION);
    out.setFrameBuffer(pixels.data(), 1, size_t(linear.width()));
    out.writePixels(linear.height());
  } catch (const std::exception& e) {
    throwRuntime("cannot write '{}': {}", path, e.what());
  }
  file.commit();
}

}  // namespace mirage
