// The pixel size an image file's header claims, read before any decoder sees the file: the
// decoders (stb, OpenEXR) answer an absurd header with a generic failure ("unknown image type",
// "unexpected end of file") or, worse, an allocation; mirage answers with the size and the
// limit it breaks (core/image.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>

namespace mirage {

struct ClaimedSize {
  int64_t width = 0, height = 0;
};

// PNG: the IHDR chunk's width and height. OpenEXR: the dataWindow attribute of the first
// header (single part and scanline or tiled alike). Nothing for other formats, or for a header
// too short or malformed to say (the decoder then gives its own message).
std::optional<ClaimedSize> claimedPngSize(const unsigned char* data, size_t size);
std::optional<ClaimedSize> claimedExrSize(const unsigned char* data, size_t size);

}  // namespace mirage
