// The ground truth against closed-form reflections: on sphere-over-checker, the checker cell and
// colour seen in the mirror sphere at sampled pixels equal those of the analytic reflection off
// the exact sphere (centre (0, 1.25, 0), radius 1) onto the floor plane y = 0.
#include <gtest/gtest.h>

#include "raytrace/tracer.h"
#include "scene/builtin_scenes.h"
#include "shading/shading.h"

namespace mirage {
namespace {

namespace sh = shading;

// Smallest t > 0 where the ray meets the sphere, or -1.
float hitSphere(const Ray& r, vec3 c, float radius) {
  vec3 oc = r.origin - c;
  float b = glm::dot(oc, r.direction), cc = glm::dot(oc, oc) - radius * radius;
  float disc = b * b - cc;
  if (disc < 0.0f) return -1.0f;
  float t = -b - std::sqrt(disc);
  return t > 0.0f ? t : -1.0f;
}

bool hitsBox(const Ray& r, const Bounds3& b) {
  float t0 = 0.0f, t1 = kInfinity;
  for (int a = 0; a < 3; ++a) {
    float inv = 1.0f / r.direction[a];
    float n = (b.lo[a] - r.origin[a]) * inv, f = (b.hi[a] - r.origin[a]) * inv;
    if (n > f) std::swap(n, f);
    t0 = std::max(t0, n);
    t1 = std::min(t1, f);
  }
  return t0 <= t1;
}

TEST(RaytraceAnalytic, MirrorSphereReflectsTheCheckerFloorExactly) {
  Scene scene = makeBuiltinScene("sphere-over-checker");
  EnvironmentMap env = EnvironmentMap::sky(scene.light, 32);
  RayTracer tracer(scene, env);
  tracer.prepare(0.0f);
  View view(scene.camera(), {360, 256});
  const vec3 centre(0.0f, 1.25f, 0.0f);
  std::vector<Bounds3> boxes;
  for (int i = 0; i < int(scene.instances.size()); ++i)
    if (scene.instances[size_t(i)].name.find("box") != std::string::npos)
      boxes.push_back(scene.instanceBounds(i));
  const Material& floor = scene.materials[size_t(scene.instances[0].material)];

  int checked = 0, light_cells = 0, dark_cells = 0;
  for (int y = 0; y < 256; y += 2)
    for (int x = 0; x < 360; x += 2) {
      Ray primary = view.primaryRay(float(x) + 0.5f, float(y) + 0.5f);
      float t = hitSphere(primary, centre, 1.0f);
      if (t < 0.0f) continue;
      vec3 p = primary.at(t), n = glm::normalize(p - centre);
      // Stay away from the silhouette, where the tessellation and the sphere disagree most.
      if (glm::dot(n, -primary.direction) < 0.25f) continue;
      Ray reflected{p, sh::reflect_direction(primary.direction, n), 0.0f, kInfinity};
      if (reflected.direction.y >= -1e-3f) continue;  // misses the floor
      float tf = -p.y / reflected.direction.y;
      vec3 q = reflected.at(tf);
      if (std::abs(q.x) > 7.9f || std::abs(q.z) > 7.9f) continue;
      bool occluded = false;
      for (const Bounds3& b : boxes) occluded = occluded || hitsBox(reflected, b);
      if (occluded) continue;
      vec2 uv(q.x + 8.0f, 8.0f - q.z);  // the floor quad's texture coordinates
      vec2 frac = glm::fract(uv);
      if (glm::min(glm::min(frac.x, 1.0f - frac.x), glm::min(frac.y, 1.0f - frac.y)) < 0.03f)
        continue;
      bool light = int(std::floor(uv.x) + std::floor(uv.y)) % 2 == 0;
      vec3 albedo = light ? floor.albedo : floor.checker_color;
      vec3 expected = sh::shade_diffuse(albedo, vec3(0, 1, 0), scene.light.direction,
                                        scene.light.color, scene.light.ambient);
      uint64_t rays = 0;
      TracedRadiance got = tracer.trace(primary, 1, rays);
      ASSERT_EQ(rays, 1u) << "pixel " << x << "," << y;
      EXPECT_NEAR(got.distance, t, 3e-3f) << "pixel " << x << "," << y;
      EXPECT_NEAR(got.radiance.x, expected.x, 1e-4f) << "pixel " << x << "," << y;
      EXPECT_NEAR(got.radiance.y, expected.y, 1e-4f) << "pixel " << x << "," << y;
      EXPECT_NEAR(got.radiance.z, expected.z, 1e-4f) << "pixel " << x << "," << y;
      ++checked;
      (light ? light_cells : dark_cells)++;
    }
  // The view shows the floor's reflection over a large part of the sphere.
  EXPECT_GT(checked, 300);
  EXPECT_GT(light_cells, 50);
  EXPECT_GT(dark_cells, 50);
}

TEST(RaytraceAnalytic, OrderZeroShowsReflectorBaseColour) {
  Scene scene = makeBuiltinScene("sphere-over-checker");
  EnvironmentMap env = EnvironmentMap::sky(scene.light, 16);
  RayTracer tracer(scene, env);
  tracer.prepare(0.0f);
  View view(scene.camera(), {64, 48});
  uint64_t rays = 0;
  TracedRadiance r = tracer.trace(view.primaryRay(32.0f, 24.0f), 0, rays);
  EXPECT_EQ(rays, 0u);
  EXPECT_EQ(r.radiance, scene.materials.back().albedo);
}

TEST(RaytraceAnalytic, MissesSampleTheEnvironment) {
  // An environment of two colours, the sky above the horizon and the ground below it (both
  // exact in half precision): a ray that meets nothing shows the colour of its half, whatever
  // the cube map's filtering, as long as it points well away from the horizon.
  const vec3 sky(0.25f, 0.5f, 0.75f), ground(1.0f, 0.125f, 0.0f);
  Image halves(64, 32);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 64; ++x) halves(x, y) = vec4(y < 16 ? sky : ground, 1.0f);
  const EnvironmentMap env = EnvironmentMap::equirect(halves, 16, 0.0f);
  Scene scene = makeBuiltinScene("sphere-over-checker");
  RayTracer tracer(scene, env);
  tracer.prepare(0.0f);
  uint64_t rays = 0;
  const Ray up{vec3(0, 5, 0), glm::normalize(vec3(0.1f, 1.0f, 0.2f)), 0.0f, kInfinity};
  TracedRadiance r = tracer.trace(up, 2, rays);
  EXPECT_EQ(r.distance, sh::MISS_DISTANCE);
  EXPECT_EQ(r.radiance, sky);
  // Down at 30 degrees below the horizon from far beyond the 16 x 16 floor: the ground half.
  const Ray down{vec3(0, 5, 50), glm::normalize(vec3(0.0f, -0.5f, 0.866f)), 0.0f, kInfinity};
  r = tracer.trace(down, 2, rays);
  EXPECT_EQ(r.distance, sh::MISS_DISTANCE);
  EXPECT_EQ(r.radiance, ground);
  EXPECT_EQ(rays, 0u);  // no reflection traced on the way
}

}  // namespace
}  // namespace mirage
