// The PSNR floors of the image tests, in one table: each the PSNR the test measured on the
// platform below when its floor was set, and the floor it must not fall under (the measurement
// less a margin for drift, or the exact-but-for-rounding bar of 60 dB where two renderers should
// agree). Measured on Mesa 22.3.6 llvmpipe (LLVM 15.0.6, 256 bits; OpenGL 4.5 core, headless
// EGL), Embree 3.13.5, 2 threads of an Intel Xeon, Debian 12: the release preset's tests.
//
// On another machine (a GPU), `MIRAGE_PSNR_LOG=/path/psnr.tsv scripts/test` appends every floor
// check's measurement there (test, floor name, measured dB, floor dB, the measurement here): the
// column to set the floors from there.
#pragma once

#include <limits>

namespace mirage::test {

struct PsnrFloor {
  const char* name;  // also the tag of the images written when it fails
  double floor;      // dB: the check fails below it
  double measured;   // dB: what the check measured on the platform above (the lowest of a loop)
};

namespace floors {

// The measurement of two identical images.
inline constexpr double kIdentical = std::numeric_limits<double>::infinity();

// Two renderers of the same thing: exact but for float rounding, rasteriser against Embree.
inline constexpr PsnrFloor kPlanarMirrorRoom{"planar-mirror-room", 60.0, 69.12};
inline constexpr PsnrFloor kPlanarMirrorRoomReflector{"planar-mirror-room-reflector", 60.0, 66.06};
inline constexpr PsnrFloor kPlanarTwoMirrorsByOrder{"planar-two-mirrors-by-order", 45.0, 48.37};
inline constexpr PsnrFloor kPlanarNotPlanar{"planar-not-planar", 60.0, kIdentical};
inline constexpr PsnrFloor kSsaaPlanar{"ssaa-planar", 60.0, 62.98};
inline constexpr PsnrFloor kEnvmapInfiniteReflector{"envmap-infinite-reflector", 40.0, 41.23};
inline constexpr PsnrFloor kEnvmapInfiniteAll{"envmap-infinite-all", 40.0, 46.86};
inline constexpr PsnrFloor kNoneVsOrder0{"none-vs-order0", 35.0, 60.33};
inline constexpr PsnrFloor kEnvmapBoxInBoxRoom{"envmap-box-reflector", 28.0, 33.60};
inline constexpr PsnrFloor kRipplingMirror{"rippling-mirror-reflector", 38.0, 143.16};
inline constexpr PsnrFloor kHybridSkyOnly{"hybrid-sky-only", 35.0, 35.61};

// Approximations against the ground truth: how close each method comes.
inline constexpr PsnrFloor kEnvmapSphereOverChecker{"envmap-reflector", 11.0, 12.75};
inline constexpr PsnrFloor kBillboardFloor{"billboard-floor-reflector", 40.0, 43.60};
inline constexpr PsnrFloor kBillboardSpheres9{"billboard-spheres9-reflector", 20.0, 22.34};
inline constexpr PsnrFloor kHybridObjects{"hybrid-objects", 31.0, 32.29};
inline constexpr PsnrFloor kHybridMovedVsTruth{"hybrid-moved-vs-truth", 26.0, 27.20};
inline constexpr PsnrFloor kHybridLod{"hybrid-lod", 28.5, 30.01};
inline constexpr PsnrFloor kDepthmapObjects{"depthmap-objects-reflector", 37.0, 40.57};
inline constexpr PsnrFloor kDepthmapSrdmVsLinear{"depthmap-srdm-vs-linear", 35.0, 38.98};
inline constexpr PsnrFloor kDepthmapSelfMaps{"depthmap-self-maps", 17.5, 18.79};
inline constexpr PsnrFloor kDepthmapMovedVsFresh{"depthmap-moved-vs-fresh", 45.0, 146.01};
inline constexpr PsnrFloor kDepthmapMovedVsTruth{"depthmap-moved-vs-truth", 30.0, 33.05};
inline constexpr PsnrFloor kSsrOnScreen{"ssr-on-screen", 32.0, 34.31};
inline constexpr PsnrFloor kZexelMirrorRoomMatched{"zexel-mirror-room-matched", 24.0, 24.31};
inline constexpr PsnrFloor kZexelMirrorRoomParallax{"zexel-mirror-room-parallax", 19.0, 24.31};
inline constexpr PsnrFloor kZexelCurved{"zexel-curved-reflector", 23.0, 25.41};

// Every floor, for the table's own test.
inline constexpr const PsnrFloor* kAll[] = {&kPlanarMirrorRoom,
                                            &kPlanarMirrorRoomReflector,
                                            &kPlanarTwoMirrorsByOrder,
                                            &kPlanarNotPlanar,
                                            &kSsaaPlanar,
                                            &kEnvmapInfiniteReflector,
                                            &kEnvmapInfiniteAll,
                                            &kNoneVsOrder0,
                                            &kEnvmapBoxInBoxRoom,
                                            &kRipplingMirror,
                                            &kHybridSkyOnly,
                                            &kEnvmapSphereOverChecker,
                                            &kBillboardFloor,
                                            &kBillboardSpheres9,
                                            &kHybridObjects,
                                            &kHybridMovedVsTruth,
                                            &kHybridLod,
                                            &kDepthmapObjects,
                                            &kDepthmapSrdmVsLinear,
                                            &kDepthmapSelfMaps,
                                            &kDepthmapMovedVsFresh,
                                            &kDepthmapMovedVsTruth,
                                            &kSsrOnScreen,
                                            &kZexelMirrorRoomMatched,
                                            &kZexelMirrorRoomParallax,
                                            &kZexelCurved};

}  // namespace floors
}  // namespace mirage::test
