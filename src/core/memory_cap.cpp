#include "core/memory_cap.h"

#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdlib>

#include "core/error.h"

namespace mirage {

namespace {
std::atomic<uint64_t> g_max_memory{kDefaultMaxMemory};
constexpr uint64_t kMinCap = uint64_t(1) << 20, kMaxCap = uint64_t(1) << 40;
}  // namespace

uint64_t maxMemory() {
  return g_max_memory.load(std::memory_order_relaxed);
}
void setMaxMemory(uint64_t bytes) {
  g_max_memory.store(bytes, std::memory_order_relaxed);
}

uint64_t parseByteSize(const std::string& option, const std::string& text) {
  auto bad = [&]() -> uint64_t {
    throwInput("{} {}: expected a size such as 512M, 4G or a byte count, in 1M..1T", option, text);
  };
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  double value = 0.0;
  auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr == begin || !std::isfinite(value) || value < 0.0) return bad();
  std::string unit(ptr, end);
  for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
  if (unit.size() > 1 && unit.back() == 'B') unit.pop_back();
  if (unit.size() > 1 && unit.back() == 'I') unit.pop_back();
  int shift = 0;
  if (unit == "K")
    shift = 10;
  else if (unit == "M")
    shift = 20;
  else if (unit == "G")
    shift = 30;
  else if (unit == "T")
    shift = 40;
  else if (!(unit.empty() || unit == "B"))
    return bad();
  const double bytes = std::ldexp(value, shift);
  if (!(bytes >= double(kMinCap) && bytes <= double(kMaxCap))) return bad();
  return uint64_t(bytes);
}

std::string formatBytes(uint64_t bytes) {
  static const char* const units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  double value = double(bytes);
  while (value >= 1024.0 && unit < 6) value /= 1024.0, ++unit;
  if (unit == 0) return fmt::format("{} B", bytes);
  return fmt::format("{:.{}f} {}", value, value < 10.0 ? 1 : 0, units[unit]);
}

void checkAllocation(const std::string& file, const std::string& what, uint64_t bytes,
                     uint64_t cap) {
  if (bytes > cap)
    throwInput("{}: {} needs {}; --max-memory allows {} per file", file, what,
               bytes == UINT64_MAX ? std::string("more than 16 EiB") : formatBytes(bytes),
               formatBytes(cap));
}

}  // namespace mirage
