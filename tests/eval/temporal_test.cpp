// The temporal error (eval/temporal.h) against hand values: a constant error does not flicker,
// an error that alternates by d changes by d every frame, only pixels that are reflector pixels
// in both frames count, and the first frame has none.
#include <gtest/gtest.h>

#include <cmath>

#include "eval/temporal.h"

namespace mirage {
namespace {

Image filled(float v) { return Image(4, 2, vec4(v, v, v, 1.0f)); }

TEST(TemporalError, AConstantErrorDoesNotFlicker) {
  TemporalError t;
  IdImage ids(4, 2, 1u);
  // The reference changes, the method follows it 0.2 off: the error is the same every frame.
  for (float r : {0.1f, 0.5f, 0.3f}) t.add(filled(r + 0.2f), filled(r), ids);
  ASSERT_EQ(t.perFrame().size(), 3u);
  EXPECT_TRUE(std::isnan(t.perFrame()[0]));
  EXPECT_NEAR(t.perFrame()[1], 0.0, 1e-7);
  EXPECT_NEAR(t.mean(), 0.0, 1e-7);
}

TEST(TemporalError, AnAlternatingErrorChangesByItsSwingOnSharedReflectorPixels) {
  TemporalError t;
  IdImage first(4, 2, 1u), second(4, 2, 1u);
  second(0, 0) = 0;  // not a reflector in the second frame: left out of its change
  Image reference = filled(0.5f);
  Image off = filled(0.6f);
  off(0, 0) = vec4(9.0f);  // would dominate were it counted
  t.add(filled(0.4f), reference, first);  // error -0.1
  t.add(off, reference, second);          // error +0.1: a change of 0.2
  t.add(filled(0.4f), reference, first);  // back: 0.2 again, pixel (0, 0) still left out
  EXPECT_NEAR(t.perFrame()[1], 0.2, 1e-6);
  EXPECT_NEAR(t.perFrame()[2], 0.2, 1e-6);
  EXPECT_NEAR(t.mean(), 0.2, 1e-6);
  // The reference's own change: the reference against black.
  TemporalError own;
  own.add(filled(0.5f), filled(0.0f), first);
  own.add(filled(0.8f), filled(0.0f), first);
  EXPECT_NEAR(own.mean(), 0.3, 1e-6);
}

TEST(TemporalError, NoSharedReflectorPixelIsNoFigure) {
  TemporalError t;
  t.add(filled(0.1f), filled(0.0f), IdImage(4, 2, 1u));
  t.add(filled(0.2f), filled(0.0f), IdImage(4, 2, 0u));
  EXPECT_TRUE(std::isnan(t.perFrame()[1]));
  EXPECT_TRUE(std::isnan(t.mean()));
}

}  // namespace
}  // namespace mirage
