#include "core/image_header.h"

#include <cstring>
#include <string_view>

namespace mirage {

namespace {

uint32_t bigEndian32(const unsigned char* p) {
  return uint32_t(p[0]) << 24 | uint32_t(p[1]) << 16 | uint32_t(p[2]) << 8 | uint32_t(p[3]);
}

int32_t littleEndian32(const unsigned char* p) {
  const uint32_t u =
      uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
  int32_t v;
  std::memcpy(&v, &u, 4);
  return v;
}

// The NUL-terminated string at `at` (at most 255 bytes, as OpenEXR's long names allow), or
// nothing if it runs past the end.
std::optional<std::string_view> cString(const unsigned char* data, size_t size, size_t at) {
  for (size_t i = at; i < size && i < at + 256; ++i)
    if (data[i] == 0) return std::string_view(reinterpret_cast<const char*>(data + at), i - at);
  return std::nullopt;
}

}  // namespace

std::optional<ClaimedSize> claimedPngSize(const unsigned char* data, size_t size) {
  static const unsigned char signature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size < 24 || std::memcmp(data, signature, 8) != 0 || std::memcmp(data + 12, "IHDR", 4) != 0)
    return std::nullopt;
  return ClaimedSize{int64_t(bigEndian32(data + 16)), int64_t(bigEndian32(data + 20))};
}

std::optional<ClaimedSize> claimedExrSize(const unsigned char* data, size_t size) {
  // Magic (4 bytes), version and flags (4), then attributes: name\0 type\0 size(int32) value,
  // up to an empty name.
  if (size < 8 || littleEndian32(data) != 20000630) return std::nullopt;
  size_t at = 8;
  while (at < size) {
    const auto name = cString(data, size, at);
    if (!name || name->empty()) return std::nullopt;
    at += name->size() + 1;
    const auto type = cString(data, size, at);
    if (!type) return std::nullopt;
    at += type->size() + 1;
    if (at + 4 > size) return std::nullopt;
    const int32_t length = littleEndian32(data + at);
    at += 4;
    if (length < 0 || uint64_t(length) > size - at) return std::nullopt;
    if (*name == "dataWindow" && *type == "box2i" && length == 16) {
      const int64_t x0 = littleEndian32(data + at), y0 = littleEndian32(data + at + 4);
      const int64_t x1 = littleEndian32(data + at + 8), y1 = littleEndian32(data + at + 12);
      return ClaimedSize{x1 - x0 + 1, y1 - y0 + 1};
    }
    at += size_t(length);
  }
  return std::nullopt;
}

}  // namespace mirage
