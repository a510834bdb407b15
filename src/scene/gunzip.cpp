#include "scene/gunzip.h"

#include <algorithm>
#include <limits>

#include <zlib.h>

#include "core/error.h"
#include "core/memory_cap.h"

namespace mirage {

bool isGzip(std::string_view bytes) {
  return bytes.size() >= 2 && uint8_t(bytes[0]) == 0x1f && uint8_t(bytes[1]) == 0x8b;
}

std::string gunzip(const std::string& name, std::string_view bytes, uint64_t max_bytes) {
  z_stream zs{};
  // 16 + MAX_WBITS: expect a gzip header and trailer (CRC and length are checked by zlib).
  if (inflateInit2(&zs, 16 + MAX_WBITS) != Z_OK) throwRuntime("{}: zlib failed to start", name);
  struct Guard {
    z_stream* zs;
    ~Guard() { inflateEnd(zs); }
  } guard{&zs};

  std::string out;
  // Start at the size the gzip trailer records (ISIZE: the input's length mod 2^32, exact for one
  // member under 4 GiB) or, failing that, a typical compression ratio; grow geometrically, never
  // past the cap (+1 byte, to tell "exactly the cap" from "more").
  const uint64_t cap = std::min<uint64_t>(max_bytes, std::numeric_limits<size_t>::max() / 2);
  uint64_t guess = uint64_t(bytes.size()) * 4;
  if (bytes.size() >= 18) {
    uint32_t isize = 0;
    for (int i = 0; i < 4; ++i)
      isize |= uint32_t(uint8_t(bytes[bytes.size() - 4 + size_t(i)])) << (8 * i);
    // Trust it only as far as deflate can expand (at most 1032:1): a truncated or forged trailer
    // must not make a small file allocate gigabytes. +1: the last inflate call ends the stream.
    if (isize > 0) guess = std::min<uint64_t>(uint64_t(isize) + 1, uint64_t(bytes.size()) * 1032);
  }
  out.resize(size_t(std::min<uint64_t>(cap + 1, std::max<uint64_t>(guess, 4096))));
  size_t produced = 0;
  const auto* in = reinterpret_cast<const Bytef*>(bytes.data());
  size_t in_left = bytes.size();

  for (;;) {
    if (produced == out.size()) {
      if (produced > cap)
        throwInput("{}: decompresses to more than {}, what --max-memory allows per file", name,
                   formatBytes(max_bytes));
      out.resize(size_t(std::min<uint64_t>(cap + 1, uint64_t(out.size()) * 2)));
    }
    // zlib counts in 32-bit unsigned ints: feed at most 1 GiB per call.
    uInt in_chunk = uInt(std::min<size_t>(in_left, size_t(1) << 30));
    uInt out_chunk = uInt(std::min<size_t>(out.size() - produced, size_t(1) << 30));
    zs.next_in = const_cast<Bytef*>(in);
    zs.avail_in = in_chunk;
    zs.next_out = reinterpret_cast<Bytef*>(out.data() + produced);
    zs.avail_out = out_chunk;
    int rc = inflate(&zs, Z_NO_FLUSH);
    size_t used = in_chunk - zs.avail_in;
    in += used;
    in_left -= used;
    produced += out_chunk - zs.avail_out;
    if (produced > cap)
      throwInput("{}: decompresses to more than {}, what --max-memory allows per file", name,
                 formatBytes(max_bytes));
    if (rc == Z_STREAM_END) {
      // Another gzip member may follow (files made with `cat a.gz b.gz`); anything else is
      // trailing padding, which gzip(1) ignores too.
      if (in_left >= 2 && isGzip({reinterpret_cast<const char*>(in), in_left})) {
        inflateReset(&zs);
        continue;
      }
      break;
    }
    if (rc == Z_BUF_ERROR && in_left == 0)
      throwInput("{}: the gzip data is truncated (it ends after {} compressed bytes)", name,
                 bytes.size());
    if (rc != Z_OK && rc != Z_BUF_ERROR)
      throwInput("{}: corrupt gzip data ({})", name, zs.msg ? zs.msg : "zlib error");
    if (rc == Z_OK && in_left == 0 && zs.avail_in == 0 && produced < out.size())
      throwInput("{}: the gzip data is truncated (it ends after {} compressed bytes)", name,
                 bytes.size());
  }
  out.resize(produced);
  return out;
}

}  // namespace mirage
