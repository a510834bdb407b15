// The shared shading functions, called on the CPU exactly as the shaders call them.
#include <gtest/gtest.h>

#include "scene/material.h"
#include "shading/shading.h"
#include "shading/tonemap.h"

namespace mirage {
namespace {

namespace sh = shading;

TEST(Shading, DiffuseIsAmbientPlusClampedLambert) {
  vec3 c = sh::shade_diffuse(vec3(0.5f), vec3(0, 1, 0), glm::normalize(vec3(0, 1, 1)), vec3(1.0f),
                             vec3(0.2f));
  EXPECT_NEAR(c.x, 0.5f * (0.2f + std::sqrt(0.5f)), 1e-6f);
  // Facing away from the light: ambient only.
  c = sh::shade_diffuse(vec3(0.5f), vec3(0, -1, 0), vec3(0, 1, 0), vec3(1.0f), vec3(0.2f));
  EXPECT_NEAR(c.y, 0.1f, 1e-6f);
}

TEST(Shading, FresnelSchlickEndpoints) {
  EXPECT_NEAR(sh::fresnel_schlick(0.04f, 1.0f), 0.04f, 1e-7f);
  EXPECT_NEAR(sh::fresnel_schlick(0.04f, 0.0f), 1.0f, 1e-7f);
  EXPECT_NEAR(sh::fresnel_schlick(0.04f, 0.5f), 0.04f + 0.96f * 0.03125f, 1e-6f);
  EXPECT_NEAR(sh::fresnel_schlick(1.0f, 0.3f), 1.0f, 1e-7f);
}

TEST(Shading, AttenuationHalvesAtItsRange) {
  EXPECT_FLOAT_EQ(sh::distance_attenuation(0.0f, 2.0f), 1.0f);
  EXPECT_FLOAT_EQ(sh::distance_attenuation(2.0f, 2.0f), 0.5f);
  EXPECT_FLOAT_EQ(sh::distance_attenuation(5.0f, 0.0f), 1.0f);  // off
  EXPECT_FLOAT_EQ(sh::distance_attenuation(sh::MISS_DISTANCE, 2.0f), 0.0f);
}

TEST(Shading, ReflectorMixesBaseAndTintedReflection) {
  Material m = Material::mirror("m", vec3(0.2f, 0.0f, 0.0f), vec3(1.0f, 0.5f, 1.0f));
  m.reflectivity = 0.5f;
  sh::MaterialData d = m.gpuData();
  vec3 c = sh::shade_reflector(d, 1.0f, 1.0f, vec3(1.0f));
  EXPECT_NEAR(c.x, 0.5f * 0.2f + 0.5f * 1.0f, 1e-6f);
  EXPECT_NEAR(c.y, 0.5f * 0.0f + 0.5f * 0.5f, 1e-6f);
  EXPECT_EQ(sh::reflector_base(d), vec3(0.2f, 0.0f, 0.0f));
}

TEST(Shading, ReflectAndFacingNormal) {
  vec3 r = sh::reflect_direction(glm::normalize(vec3(1, -1, 0)), vec3(0, 1, 0));
  EXPECT_NEAR(r.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(r.y, std::sqrt(0.5f), 1e-6f);
  // Seen from behind, the normal flips; the geometric normal's orientation does not matter.
  vec3 n(0, 0, 1);
  EXPECT_EQ(sh::facing_normal(n, vec3(0, 0, -1), vec3(0, 0, -1)), -n);
  EXPECT_EQ(sh::facing_normal(n, vec3(0, 0, -1), vec3(0, 0, 1)), n);
}

TEST(Shading, CheckerCellsAlternate) {
  vec3 a(1.0f), b(0.0f);
  EXPECT_EQ(sh::checker_albedo(vec2(0.5f, 0.5f), 1.0f, a, b), a);
  EXPECT_EQ(sh::checker_albedo(vec2(1.5f, 0.5f), 1.0f, a, b), b);
  EXPECT_EQ(sh::checker_albedo(vec2(-0.5f, 0.5f), 1.0f, a, b), b);
  EXPECT_EQ(sh::checker_albedo(vec2(1.5f, 1.5f), 1.0f, a, b), a);
  EXPECT_EQ(sh::checker_albedo(vec2(0.25f, 0.75f), 2.0f, a, b), b);
}

TEST(Shading, DisplayTransform) {
  vec3 c = sh::display_transform(vec3(0.0f, 1.0f, 4.0f), 1.0f, MIRAGE_TONEMAP_CLAMP);
  EXPECT_FLOAT_EQ(c.x, 0.0f);
  EXPECT_FLOAT_EQ(c.y, 1.0f);
  EXPECT_FLOAT_EQ(c.z, 1.0f);
  EXPECT_NEAR(sh::srgb_encode(0.5f), 0.735357f, 1e-5f);
  EXPECT_NEAR(sh::tonemap_channel(1.0f, MIRAGE_TONEMAP_REINHARD), 0.5f, 1e-6f);
  EXPECT_LT(sh::tonemap_channel(1000.0f, MIRAGE_TONEMAP_ACES), 1.0001f);
}

}  // namespace
}  // namespace mirage
