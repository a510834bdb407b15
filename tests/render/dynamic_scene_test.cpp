// Dynamic scenes on the GPU: the scene's versions say exactly what changed (one moving instance,
// the light, a deforming shape), and a rippling mirror drawn from the GPU scene's deformed
// vertices reflects the sky as the ray tracer's deformed mesh does.
#include <gtest/gtest.h>

#include "methods/frame.h"
#include "support/gl_test.h"
#include "support/image_check.h"
#include "support/render_pair.h"
#include "support/scenes.h"

namespace mirage::test {
namespace {

class DynamicScene : public GlTest {};

TEST_F(DynamicScene, VersionsCountOnlyWhatChanged) {
  const Scene scene = makeBuiltinScene("mirror-room");
  FrameRenderer renderer(scene, {32, 32});
  GpuScene& gpu = renderer.gpu();
  const int teapot = instanceNamed(scene, "teapot"), room = instanceNamed(scene, "room");
  const uint64_t v0 = gpu.version(), teapot0 = gpu.instanceVersion(teapot),
                 room0 = gpu.instanceVersion(room), light0 = gpu.lightVersion();
  gpu.setTime(0.0f);  // the same time: nothing
  EXPECT_EQ(gpu.version(), v0);
  gpu.setTime(1.0f);
  EXPECT_EQ(gpu.version(), v0 + 1);
  EXPECT_EQ(gpu.instanceVersion(teapot), teapot0 + 1);
  EXPECT_EQ(gpu.instanceVersion(room), room0);  // the room stands still
  EXPECT_EQ(gpu.lightVersion(), light0 + 1);    // the light swings
  EXPECT_NEAR(glm::dot(gpu.light().direction, scene.lightAt(1.0f).direction), 1.0f, 1e-6f);
  EXPECT_EQ(gpu.shapeVersion(teapot), 0u);  // rigid: its shape never changes
}

TEST_F(DynamicScene, DeformingMeshIsUploadedAndBoundsHoldIt) {
  const Scene scene = makeBuiltinScene("ripple-pool");
  FrameRenderer renderer(scene, {32, 32});
  GpuScene& gpu = renderer.gpu();
  const int pool = instanceNamed(scene, "pool");
  const uint64_t shape0 = gpu.shapeVersion(pool), floor0 = gpu.instanceVersion(0);
  gpu.setTime(0.7f);
  EXPECT_EQ(gpu.shapeVersion(pool), shape0 + 1);
  EXPECT_EQ(gpu.instanceVersion(0), floor0);
  // What the GPU draws, against the ripple's closed form (scene/deformation.h) at t = 0.7 s: every
  // rest vertex p of the flat pool (normal +Y) raised by h = A e^(-r/D) sin(k r - w t), with
  // r = sqrt(|p - c|^2 + (L/4)^2), k = 2 pi / L, w = k v (the pool's A, L, v, D, c).
  const Deformation& d = scene.instances[size_t(pool)].deformation;
  const Mesh& rest = scene.meshes[size_t(scene.instances[size_t(pool)].mesh)];
  const std::vector<vec3> uploaded = gpu.uploadedPositions(pool);
  ASSERT_EQ(uploaded.size(), rest.positions.size());
  const double k = 2.0 * M_PI / d.wavelength, w = k * d.speed;
  int wrong = 0;
  double highest = 0.0;
  for (size_t i = 0; i < uploaded.size(); ++i) {
    const vec3 p = rest.positions[i];
    const double dx = p.x - d.center.x, dy = p.y - d.center.y, dz = p.z - d.center.z;
    const double r = std::sqrt(dx * dx + dy * dy + dz * dz + d.wavelength * d.wavelength / 16.0);
    const double h = d.amplitude * std::exp(-r / d.decay) * std::sin(k * r - w * 0.7);
    highest = std::max(highest, std::abs(h));
    const vec3 expected(p.x, float(p.y + h), p.z);
    if (glm::distance(uploaded[i], expected) > 1e-5f && wrong++ < 5)
      ADD_FAILURE() << "vertex " << i << ": uploaded (" << uploaded[i].x << ", " << uploaded[i].y
                    << ", " << uploaded[i].z << "), the ripple puts it at y = " << expected.y;
  }
  EXPECT_EQ(wrong, 0);
  EXPECT_GT(highest, 0.5 * d.amplitude * std::exp(-4.0 / d.decay));  // it does ripple
  const Bounds3 b = gpu.instanceBounds(pool);
  for (const vec3& p : gpu.mesh(pool).positions)
    EXPECT_TRUE(b.contains(transformPoint(gpu.instanceMatrix(pool), p)));
}

// A rippling mirror square under the sky and nothing else, its waves low enough and the eye high
// enough that no reflected ray meets the mirror again: every one reaches the sky, so
// `envmap-infinite` is exact but for rasterisation, given the same deformed normals.
Scene ripplingMirrorInSky() {
  Scene s;
  s.name = "rippling-mirror-in-sky";
  const int grid = addMesh(s, procedural::quad(3.0f, 3.0f, 1.0f, 96, 96));
  const int mirror = addMaterial(s, Material::mirror("mirror"));
  const int pool = addInstance(s, "pool", grid, mirror, {});
  Deformation& d = s.instances[size_t(pool)].deformation;
  d.kind = Deformation::Kind::kRipple;
  d.amplitude = 0.012f;
  d.wavelength = 0.6f;
  d.speed = 0.3f;
  d.center = vec3(0.4f, 0.0f, -0.2f);
  finishScene(s, vec3{0.0f, 2.4f, 2.0f}, vec3{0.0f, 0.0f, 0.0f}, 50.0f);
  return s;
}

TEST_F(DynamicScene, RipplingMirrorMatchesTheRayTracerAtEveryTime) {
  const Scene scene = ripplingMirrorInSky();
  FrameSettings settings;
  settings.order = 1;
  settings.mip = false;  // the ray tracer samples level 0
  const ivec2 size{256, 192};
  const RenderPair at0 = renderWithTruth(scene, "envmap-infinite", size, settings, {}, 0.0f);
  const RenderPair later = renderWithTruth(scene, "envmap-infinite", size, settings, {}, 0.9f);
  for (const RenderPair* p : {&at0, &later}) {
    EXPECT_GT(countNonZero(p->cpu_ids), 20000u);
    // The same rays through the same deformed triangles: equal but for float rounding.
    EXPECT_TRUE(imagesEqual(p->gpu, p->cpu, kFloatRounding, &p->cpu_ids, "rippling-mirror"));
  }
  // The waves moved: the two times differ far more (10 dB) than the GPU and the ray tracer do.
  const double moved = psnrFromMse(meanSquaredError(at0.cpu, later.cpu, &at0.cpu_ids));
  const double agree = psnrFromMse(meanSquaredError(later.gpu, later.cpu, &later.cpu_ids));
  EXPECT_LT(moved + 10.0, agree);
}

}  // namespace
}  // namespace mirage::test
