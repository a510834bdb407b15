// The PSNR floors of the image tests, in one table: each the PSNR the test measured on the
// platform below, and the floor it must not fall under — the measurement less a margin for drift
// of at most 3 dB, or, with a stated reason, further below (the exact-but-for-rounding bar of
// 60 dB where two renderers of one thing should agree). Measured on Mesa 22.3.6 llvmpipe
// (LLVM 15.0.6, 256 bits; OpenGL 4.5 core, headless EGL), Embree 3.13.5, 2 threads of an AMD
// EPYC, Debian 12: the release preset's tests. `scripts/psnr-floors` re-measures the `measured`
// column (it runs the tests with MIRAGE_PSNR_LOG set; `--write` rewrites this file), and its
// `--check` (ctest `PsnrFloors.TheTableIsTheTestsAndItsMeasurements`) fails where a floor lies
// more than 3 dB below its measurement without a reason, where a floor of the table is used by
// no test, or where a test compares a PSNR with a bare number instead of a floor of this table.
//
// On another machine (a GPU), `MIRAGE_PSNR_LOG=/path/psnr.tsv scripts/test` appends every floor
// check's measurement there (test, floor name, measured dB, floor dB, the measurement here): the
// column to set the floors from there.
#pragma once

namespace mirage::test {

struct PsnrFloor {
  const char* name;  // also the tag of the images written when it fails
  double floor;      // dB: the check fails below it
  double measured;   // dB: what the check measured on the platform above (the lowest of a loop)
  const char* reason = nullptr;  // why the floor lies more than 3 dB below the measurement
};

// The largest margin a floor may keep below its measurement without a reason.
inline constexpr double kFloorMargin = 3.0;

namespace floors {

inline constexpr const char* kExactBar =
    "two renderers of one exact thing: the bar for agreement but for float rounding";

// Two renderers of the same thing: exact but for float rounding, rasteriser against Embree.
inline constexpr PsnrFloor kPlanarMirrorRoom{"planar-mirror-room", 60.0, 69.12, kExactBar};
inline constexpr PsnrFloor kPlanarMirrorRoomReflector{"planar-mirror-room-reflector", 60.0, 66.06,
                                                      kExactBar};
inline constexpr PsnrFloor kPlanarTwoMirrorsByOrder{"planar-two-mirrors-by-order", 46.0, 48.37};
inline constexpr PsnrFloor kSsaaPlanar{"ssaa-planar", 60.0, 62.98};
inline constexpr PsnrFloor kEnvmapInfiniteReflector{"envmap-infinite-reflector", 40.0, 41.23};
inline constexpr PsnrFloor kEnvmapInfiniteAll{"envmap-infinite-all", 44.0, 46.86};
inline constexpr PsnrFloor kNoneVsOrder0{"none-vs-order0", 57.5, 60.33};
inline constexpr PsnrFloor kEnvmapBoxInBoxRoom{"envmap-box-reflector", 31.0, 33.60};
// A floor alone under a mirror sphere, hybrid's background through its open box, under 2x2.
inline constexpr PsnrFloor kHybridFloorThroughTheBox{"hybrid-floor-through-the-box", 28.0, 30.52};
inline constexpr PsnrFloor kHybridSkyOnly{"hybrid-sky-only", 35.0, 35.61};
inline constexpr PsnrFloor kSsrFallbackIsEnvmapBox{"ssr-fallback-is-envmap-box", 74.0, 76.97};
// One method's captures kept by a policy against the same captures made afresh.
inline constexpr PsnrFloor kRecaptureCaughtUp{"recapture-caught-up", 35.0, 37.90};
inline constexpr PsnrFloor kRecaptureCarriedSpin{"recapture-carried-spin", 41.5, 44.44};
// The matched reference against the converged one (compare's noise floor), 96x64 under 2x2.
inline constexpr PsnrFloor kReferenceNoiseFloor{"reference-noise-floor", 25.0, 25.96};

// Approximations against the ground truth: how close each method comes.
inline constexpr PsnrFloor kEnvmapSphereOverChecker{"envmap-reflector", 11.0, 12.75};
inline constexpr PsnrFloor kBillboardFloor{"billboard-floor-reflector", 41.0, 43.60};
inline constexpr PsnrFloor kBillboardGroupsBesideAReflector{"billboard-groups-beside-a-reflector",
                                                            27.5, 30.31};
// A room of one mesh in the environment layer, its walls planar billboards, under 2x2.
inline constexpr PsnrFloor kImpostorRoomOfOneMesh{"impostor-room-of-one-mesh", 26.5, 29.02};
inline constexpr PsnrFloor kBillboardSpheres9{"billboard-spheres9-reflector", 20.0, 22.36};
inline constexpr PsnrFloor kHybridObjects{"hybrid-objects", 31.0, 33.44};
inline constexpr PsnrFloor kHybridMovedVsTruth{"hybrid-moved-vs-truth", 26.0, 28.72};
inline constexpr PsnrFloor kHybridLod{"hybrid-lod", 28.5, 29.05};
inline constexpr PsnrFloor kDepthmapObjects{"depthmap-objects-reflector", 38.0, 40.81};
inline constexpr PsnrFloor kDepthmapSrdmVsLinear{"depthmap-srdm-vs-linear", 36.0, 38.87};
inline constexpr PsnrFloor kDepthmapSelfMaps{"depthmap-self-maps", 17.5, 18.79};
inline constexpr PsnrFloor kDepthmapMovedVsTruth{"depthmap-moved-vs-truth", 30.5, 33.43};
inline constexpr PsnrFloor kSsrOnScreen{"ssr-on-screen", 32.0, 34.37};
inline constexpr PsnrFloor kZexelMirrorRoomMatched{"zexel-mirror-room-matched", 24.0, 24.31};
inline constexpr PsnrFloor kZexelCurved{"zexel-curved-reflector", 23.0, 25.41};

// Every floor, for the table's own test.
inline constexpr const PsnrFloor* kAll[] = {
    &kPlanarMirrorRoom,
    &kPlanarMirrorRoomReflector,
    &kPlanarTwoMirrorsByOrder,
    &kSsaaPlanar,
    &kEnvmapInfiniteReflector,
    &kEnvmapInfiniteAll,
    &kNoneVsOrder0,
    &kEnvmapBoxInBoxRoom,
    &kHybridSkyOnly,
    &kHybridFloorThroughTheBox,
    &kSsrFallbackIsEnvmapBox,
    &kRecaptureCaughtUp,
    &kRecaptureCarriedSpin,
    &kReferenceNoiseFloor,
    &kEnvmapSphereOverChecker,
    &kBillboardFloor,
    &kBillboardSpheres9,
    &kImpostorRoomOfOneMesh,
    &kBillboardGroupsBesideAReflector,
    &kHybridObjects,
    &kHybridMovedVsTruth,
    &kHybridLod,
    &kDepthmapObjects,
    &kDepthmapSrdmVsLinear,
    &kDepthmapSelfMaps,
    &kDepthmapMovedVsTruth,
    &kSsrOnScreen,
    &kZexelMirrorRoomMatched,
    &kZexelCurved,
};

}  // namespace floors
}  // namespace mirage::test
