// shading/proxy.h compiled as GLSL gives what its C++ compile gives: random rays against random
// boxes and quads, run by a compute shader and by the C++ functions the tests check by hand.
#include <gtest/gtest.h>

#include <random>

#include "gpu/buffer.h"
#include "gpu/program.h"
#include "shading/proxy.h"
#include "support/gl_test.h"

namespace mirage::test {
namespace {

struct ProxyCase {
  vec4 origin, dir, a, b, c, morph;
};
struct ProxyResult {
  vec4 box, quad, parallax, morph, sphere;
};

class ProxyGpuTest : public GlTest {};

TEST_F(ProxyGpuTest, GlslAgreesWithCpp) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  auto rand3 = [&] { return vec3(u(rng), u(rng), u(rng)); };
  const int n = 4096;
  std::vector<ProxyCase> cases(size_t{n});
  for (auto& k : cases) {
    vec3 lo = 2.0f * rand3() - vec3(1.5f), size = vec3(0.2f) + 2.0f * glm::abs(rand3());
    k.origin = vec4(lo + 0.5f * size + 0.9f * size * rand3(), 0);  // inside or near the box
    k.dir = vec4(glm::normalize(rand3() + vec3(1e-3f)), 0);
    k.a = vec4(lo, 0);
    k.b = vec4(lo + size, 0);
    k.c = vec4(lo + 0.5f * size + 0.1f * rand3(), 0);
    k.morph = vec4(2.0f * u(rng), 1.0f + u(rng) * 0.5f, 0, 0);
  }
  gpu::Buffer in(cases.size() * sizeof(ProxyCase), cases.data());
  gpu::Buffer out(cases.size() * sizeof(ProxyResult));
  gpu::Program program = gpu::Program::compute("shading/proxy_check.comp");
  program.set("u_count", n);
  program.use();
  in.bindBase(GL_SHADER_STORAGE_BUFFER, 0);
  out.bindBase(GL_SHADER_STORAGE_BUFFER, 1);
  glDispatchCompute(GLuint((n + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  std::vector<ProxyResult> gpu(cases.size());
  out.download(gpu.data(), gpu.size() * sizeof(ProxyResult));

  int box_hits = 0, quad_hits = 0, mismatches = 0;
  for (int i = 0; i < n; ++i) {
    const ProxyCase& k = cases[size_t(i)];
    const ProxyResult& g = gpu[size_t(i)];
    auto near = [](float x, float y) { return std::abs(x - y) <= 1e-4f * (1.0f + std::abs(y)); };
    int face = -1;
    float t = shading::ray_box_exit(vec3(k.origin), vec3(k.dir), vec3(k.a), vec3(k.b), face);
    box_hits += t >= 0.0f;
    bool ok = near(g.box.x, t) && int(g.box.y) == face;
    vec2 uv;
    float tq =
        shading::ray_quad(vec3(k.origin), vec3(k.dir), vec3(k.a), vec3(k.b), vec3(k.c), 0.0f, uv);
    quad_hits += tq >= 0.0f;
    ok = ok && near(g.quad.x, tq) && (tq < 0.0f || (near(g.quad.y, uv.x) && near(g.quad.z, uv.y)));
    float tp = 0.0f;
    vec3 d = shading::box_parallax_direction(vec3(k.origin), vec3(k.dir), vec3(k.a), vec3(k.b),
                                             vec3(k.c), tp);
    ok = ok && near(g.parallax.w, tp) && near(g.parallax.x, d.x) && near(g.parallax.y, d.y) &&
         near(g.parallax.z, d.z);
    vec3 m = shading::morph_direction(vec3(k.b), vec3(k.c), vec3(k.dir), k.morph.x, k.morph.y);
    ok = ok && near(g.morph.x, m.x) && near(g.morph.y, m.y) && near(g.morph.z, m.z);
    float ts = shading::ray_sphere_exit(vec3(k.origin), vec3(k.dir), vec3(k.c), k.morph.y);
    ok = ok && near(g.sphere.x, ts);
    if (!ok && ++mismatches <= 5)
      ADD_FAILURE() << "case " << i << ": GPU box (" << g.box.x << ", " << g.box.y << ") vs CPU ("
                    << t << ", " << face << "); quad " << g.quad.x << " vs " << tq;
  }
  EXPECT_EQ(mismatches, 0);
  // The cases exercise both outcomes of each test.
  EXPECT_GT(box_hits, n / 10);
  EXPECT_LT(box_hits, n - n / 10);
  EXPECT_GT(quad_hits, n / 50);
}

}  // namespace
}  // namespace mirage::test
