// Image assertions that leave evidence: on failure they write actual, expected and diff images
// to build/<preset>/test-artifacts/<suite>.<test>/ and say where.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/image.h"
#include "eval/metrics.h"
#include "support/psnr_floors.h"

namespace mirage::test {

// Writes actual/expected/diff PNGs (display-encoded inputs) for the current test; returns the
// directory.
std::string writeArtifacts(const Image& actual, const Image& expected, const std::string& tag);

// Passes when the PSNR meets the floor (support/psnr_floors.h), and with MIRAGE_PSNR_LOG set
// appends the measurement to that file. `tag` (default: the floor's name) names the images
// written on failure.
::testing::AssertionResult psnrAtLeast(const Image& actual, const Image& expected,
                                       const PsnrFloor& floor, const IdImage* mask,
                                       const std::string& tag = "");
// The same for a PSNR measured by the caller (no images to write).
::testing::AssertionResult meetsFloor(double psnr, const PsnrFloor& floor);

// Passes when no (masked) pixel's colour channel differs by more than `max_difference`: 0 for
// frames that must be the same to the bit; a float-rounding tolerance (kFloatRounding: 1e-4 of display values,
// a fortieth of an 8-bit step) for two renderers of one exact thing. On failure says the largest
// difference, where, and how many pixels are off, and writes the images.
::testing::AssertionResult imagesEqual(const Image& actual, const Image& expected,
                                       float max_difference, const IdImage* mask,
                                       const std::string& tag);
inline constexpr float kFloatRounding = 1.0e-4f;

// Passes when at most `max_fraction` of the (masked) pixels differ by more than `tolerance` in
// any channel.
::testing::AssertionResult mostPixelsWithin(const Image& actual, const Image& expected,
                                            float tolerance, double max_fraction,
                                            const IdImage* mask, const std::string& tag);

// Per pixel, whether any colour channel of `a` and `b` differs by more than 1e-5.
std::vector<bool> changedPixels(const Image& a, const Image& b);

}  // namespace mirage::test
