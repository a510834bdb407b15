// What every fuzz target shares: quiet logs, no asset directory to read from, and the contract
// the targets check — a malformed input may only ever raise InputError (exit 2 with a message);
// anything else (another exception, a crash, a sanitizer report, a hang) is a finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include <spdlog/spdlog.h>

#include "core/error.h"
#include "core/memory_cap.h"

namespace mirage::fuzz {

inline void quiet() {
  spdlog::set_level(spdlog::level::off);
  // What one input may make us allocate, well under libFuzzer's 2 GB RSS limit: a header that
  // asks for more must be refused by the checks before allocation (--max-memory).
  mirage::setMaxMemory(uint64_t(256) << 20);
  // `assets:` references resolve into a folder that does not exist: a missing file, not a read
  // of whatever the machine has.
  setenv("MIRAGE_ASSET_DIR", "/nonexistent/mirage-fuzz-assets", 1);
}

// Runs `parse` on the input; InputError is the expected answer to bad input.
template <typename F>
int run(const uint8_t* data, size_t size, F parse) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  try {
    parse(bytes);
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace mirage::fuzz

#define MIRAGE_FUZZ_TARGET(body)                                                  \
  extern "C" int LLVMFuzzerInitialize(int*, char***) {                            \
    mirage::fuzz::quiet();                                                        \
    return 0;                                                                     \
  }                                                                               \
  extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {       \
    return mirage::fuzz::run(data, size, [](const std::string& bytes) { body; }); \
  }
