// Frame sequences of `mirage render --frames N`: the name of frame i (out.png -> out_0000.png)
// and an MP4 made of PNG frames by ffmpeg, when ffmpeg is installed.
#pragma once

#include <string>

namespace mirage::app {

// `output` with the frame index before its extension: "out.png", 7 -> "out_0007.png" (at least
// four digits, more when `count` needs them).
std::string frameFileName(const std::string& output, int index, int count);
// The same names as a printf pattern ("out_%04d.png"), as ffmpeg reads them.
std::string framePattern(const std::string& output, int count);

// The ffmpeg on PATH (MIRAGE_FFMPEG overrides it), or "" when there is none.
std::string findFfmpeg();

// Encodes `pattern` (a printf pattern of PNG frames, e.g. dir/frame_%04d.png) at `fps` into the
// MP4 `output` (H.264, yuv420p), written atomically. Throws RuntimeError with ffmpeg's message
// when it fails.
void encodeMp4(const std::string& ffmpeg, const std::string& pattern, double fps,
               const std::string& output);

}  // namespace mirage::app
