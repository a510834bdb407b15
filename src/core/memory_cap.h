// The cap on what one input file may make mirage allocate (`--max-memory`, docs/reliability.md).
// Readers estimate the bytes a file's header asks for — vertices and triangles of a mesh, pixels
// of an image, the inflated size of a gzip stream — and refuse it before allocating anything, so
// that a hostile or mistaken header gets a message, not an out-of-memory kill.
#pragma once

#include <cstdint>
#include <string>

namespace mirage {

inline constexpr uint64_t kDefaultMaxMemory = uint64_t(4) << 30;  // 4 GiB

// The cap in bytes: kDefaultMaxMemory until setMaxMemory() changes it for the process.
uint64_t maxMemory();
void setMaxMemory(uint64_t bytes);

// "4G", "512M", "64k", "1.5G" or a plain byte count (binary units; a trailing "B" or "iB" is
// allowed). Throws InputError naming `option` and the allowed range (1M..1T).
uint64_t parseByteSize(const std::string& option, const std::string& text);
// "1.5 GiB", "512 MiB", "12 KiB", "100 B".
std::string formatBytes(uint64_t bytes);

// Throws InputError when `bytes` exceed the cap: "<file>: <what> needs <size>; --max-memory
// allows <cap> per file". `bytes` is an estimate computed in 64 bits (or saturated) by the caller.
// `cap` is the process's unless a caller has its own (LoadLimits::max_bytes).
void checkAllocation(const std::string& file, const std::string& what, uint64_t bytes,
                     uint64_t cap = maxMemory());

// a * b, saturated at UINT64_MAX (header counts multiplied by element sizes).
inline uint64_t saturatingMul(uint64_t a, uint64_t b) {
  return (b != 0 && a > UINT64_MAX / b) ? UINT64_MAX : a * b;
}
inline uint64_t saturatingAdd(uint64_t a, uint64_t b) {
  return a > UINT64_MAX - b ? UINT64_MAX : a + b;
}

}  // namespace mirage
