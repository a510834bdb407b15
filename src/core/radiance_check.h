// A check of Radiance HDR (.hdr) files before stb_image decodes them: Debian's stb_image loops
// forever on a run-length scanline with a zero count (found by fuzzing), so every scanline that
// stb would read as run-length encoded is walked here first, exactly as stb walks it, and a
// malformed one is an InputError naming the file and the scanline.
#pragma once

#include <cstddef>
#include <string>

namespace mirage {

// Throws InputError when `data` (a Radiance file: "#?RADIANCE" or "#?RGBE") has a truncated
// header or a run-length scanline that stb_image cannot finish; flat (uncompressed) data is
// left to stb, which reads it to the end and stops.
void checkRadianceScanlines(const std::string& name, const unsigned char* data, size_t size);

}  // namespace mirage
