#include "core/radiance_check.h"

#include <cstdio>
#include <cstring>
#include <string_view>

#include "core/error.h"

namespace mirage {

void checkRadianceScanlines(const std::string& name, const unsigned char* data, size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  if (!text.starts_with("#?RADIANCE") && !text.starts_with("#?RGBE")) return;  // not ours
  // The header ends at an empty line; the resolution line follows it.
  const size_t blank = text.find("\n\n");
  if (blank == std::string_view::npos)
    throwInput("{}: Radiance header without the empty line that ends it", name);
  const size_t line_end = text.find('\n', blank + 2);
  if (line_end == std::string_view::npos)
    throwInput("{}: Radiance file without a resolution line", name);
  const std::string resolution(text.substr(blank + 2, line_end - blank - 2));
  int height = 0, width = 0;
  char extra = 0;
  if (std::sscanf(resolution.c_str(), "-Y %d +X %d%c", &height, &width, &extra) != 2 ||
      width <= 0 || height <= 0)
    throwInput("{}: Radiance resolution line is not '-Y <height> +X <width>'", name);
  // stb decodes flat pixels when the width is outside 8..32767 or a scanline does not start
  // with the run-length marker; it then reads to the end and stops, so only RLE needs a walk.
  if (width < 8 || width >= 32768) return;
  size_t at = line_end + 1;
  auto byte = [&](int row) -> unsigned {
    if (at >= size)
      throwInput("{}: Radiance data ends inside scanline {} of {}", name, row, height);
    return data[at++];
  };
  for (int row = 0; row < height; ++row) {
    if (at + 4 > size) return;  // stb reads what is missing as zeros, flat, and stops
    const unsigned c1 = data[at], c2 = data[at + 1], len = data[at + 2];
    if (c1 != 2 || c2 != 2 || (len & 0x80)) return;  // flat from here on: stb's own rule
    const int encoded = int((data[at + 2] << 8) | data[at + 3]);
    at += 4;
    if (encoded != width)
      throwInput("{}: Radiance scanline {} is {} pixels wide, the image {}", name, row, encoded,
                 width);
    for (int channel = 0; channel < 4; ++channel) {
      int x = 0;
      while (x < width) {
        unsigned count = byte(row);
        if (count > 128) {
          count -= 128;
          byte(row);  // the run's value
        } else if (count == 0) {
          throwInput("{}: Radiance scanline {} has a run of length 0", name, row);
        } else {
          for (unsigned k = 0; k < count; ++k) byte(row);
        }
        if (int(count) > width - x)
          throwInput("{}: Radiance scanline {} runs past its {} pixels", name, row, width);
        x += int(count);
      }
    }
  }
}

}  // namespace mirage
