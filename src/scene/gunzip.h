// Gzip decompression for compressed model files (.ply.gz), streamed through zlib with a cap on
// the output so that a small "zip bomb" cannot make mirage allocate gigabytes.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace mirage {

// Whether `bytes` start with the gzip magic number (1f 8b).
bool isGzip(std::string_view bytes);

// Inflates gzip data (concatenated members too). Throws InputError naming `name` when the data is
// corrupt or truncated, or when it would inflate to more than `max_bytes`.
std::string gunzip(const std::string& name, std::string_view bytes, uint64_t max_bytes);

}  // namespace mirage
