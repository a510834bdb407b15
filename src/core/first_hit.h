// What a reflector pixel's reflected ray meets first: the ray tracer writes one code per pixel
// (RayTracer::firstHits) and the compare report attributes each method's error to these causes
// (eval/causes.h). A code packs the kind and the instance hit, so that sub-pixels that met
// different objects of one kind still count as disagreeing.
#pragma once

#include <cstdint>

namespace mirage {

enum class FirstHit : uint32_t {
  kNone = 0,         // the pixel's primary ray hit no reflector: no reflection to attribute
  kEnvironment = 1,  // the reflected ray left the scene
  kDiffuse = 2,      // it hit a diffuse object (the instance is kept)
  kSelf = 3,         // it hit the reflector it left (a concave or bumpy surface)
  kReflector = 4,    // it hit another reflector, whose own reflection the order still allows
  kBeyondOrder = 5,  // it hit a reflector after the last allowed bounce: that shows its base colour
};

// instance < 0: none (environment, or order 0 where no reflected ray is traced).
inline uint32_t encodeFirstHit(FirstHit kind, int instance) {
  return uint32_t(kind) | (uint32_t(instance + 1) << 3);
}
inline FirstHit firstHitKind(uint32_t code) {
  return FirstHit(code & 7u);
}
inline int firstHitInstance(uint32_t code) {
  return int(code >> 3) - 1;
}

}  // namespace mirage
