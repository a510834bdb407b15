#include "render/reflector_gbuffer.h"

#include <algorithm>
#include <limits>

#include "render/depth_state.h"
#include "shading/gpu_types.h"

namespace mirage {

ReflectorGBuffer::ReflectorGBuffer()
    : reflector_program_(gpu::Program::graphics(
          "render/shaders/scene.vert", "render/shaders/base_colour.frag", {"MIRAGE_GBUFFER 1"})),
      depth_program_(
          gpu::Program::graphics("render/shaders/scene.vert", "render/shaders/depth_only.frag")) {}

void ReflectorGBuffer::fit(const FrameTarget& target) {
  const ivec2 size = target.size();
  if (size == size_ && color_id_ == target.color().id() && depth_id_ == target.depth().id()) return;
  size_ = size;
  color_id_ = target.color().id();
  depth_id_ = target.depth().id();
  // Full floats: the passes reflect about this normal, and z, w hold whole numbers.
  normals_ = gpu::Texture::create2D(GL_RGBA32F, size.x, size.y);
  normals_.setFilter(GL_NEAREST, GL_NEAREST);
  with_depth_ = gpu::Framebuffer();
  with_depth_.attachColor(0, target.color());
  with_depth_.attachColor(1, target.ids());
  with_depth_.attachColor(2, normals_);
  with_depth_.attachDepth(target.depth());
  with_depth_.setDrawBuffers(3);
  with_depth_.checkComplete("reflector G-buffer");
  shading_ = gpu::Framebuffer();
  shading_.attachColor(0, target.color());
  shading_.setDrawBuffers(1);
  shading_.checkComplete("reflector G-buffer shading");
}

void ReflectorGBuffer::begin(FrameTarget& target, ScenePasses& passes, const View& view,
                             const FrameSettings& settings) {
  fit(target);
  with_depth_.bind();
  passes.begin(view, settings);
  const float zero[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(with_depth_.id(), GL_COLOR, 2, zero);
}

ReflectorPlan ReflectorGBuffer::plan(const GpuScene& gpu, const View& view,
                                     const ShadeOptions& options) const {
  const Scene& scene = gpu.scene();
  const std::vector<int> reflectors = scene.reflectorInstances();
  ReflectorPlan plan;
  plan.screen.assign(reflectors.size(), ivec4(0));
  plan.triangles.assign(reflectors.size(), ivec4(0));
  for (size_t k = 0; k < reflectors.size(); ++k) {
    const int instance = reflectors[k];
    const std::vector<int>* own = options.own;
    if (own && std::find(own->begin(), own->end(), instance) == own->end()) continue;
    const ivec4 r = screenRectangle(gpu.instanceBounds(instance), view);
    if (r.x >= r.z || r.y >= r.w) continue;
    const Mesh& mesh = scene.meshes[size_t(scene.instances[size_t(instance)].mesh)];
    const bool by_screen =
        !options.triangles || options.pass == ReflectorPass::kScreen ||
        (options.pass == ReflectorPass::kAuto && screenPassPays(mesh.triangleCount(), r));
    (by_screen ? plan.screen : plan.triangles)[k] = r;
    (by_screen ? plan.taken.screen : plan.taken.triangles) += 1;
  }
  return plan;
}

void ReflectorGBuffer::shade(const FrameTarget& target, ScenePasses& passes, const View& view,
                             const FrameSettings& settings, const gpu::Program& program,
                             const ShadeOptions& options) const {
  ShadeOptions screen_only = options;
  screen_only.triangles = nullptr;
  shade(target, passes, view, settings, program, screen_only,
        plan(passes.scene(), view, screen_only));
}

void ReflectorGBuffer::shade(const FrameTarget& target, ScenePasses& passes, const View& view,
                             const FrameSettings& settings, const gpu::Program& program,
                             const ShadeOptions& options, const ReflectorPlan& plan) const {
  if (plan.taken.screen > 0)
    drawScreen(target, passes, view, settings, program, options, plan.screen);
  if (plan.taken.triangles > 0)
    drawTriangles(target, passes, view, settings, *options.triangles, options, plan.triangles);
}

void ReflectorGBuffer::drawScreen(const FrameTarget& target, ScenePasses& passes, const View& view,
                                  const FrameSettings& settings, const gpu::Program& program,
                                  const ShadeOptions& options,
                                  const std::vector<ivec4>& rectangles) const {
  shading_.bind();
  passes.begin(view, settings);
  normals_.bind(MIRAGE_UNIT_GBUFFER_NORMAL);
  target.depth().bind(MIRAGE_UNIT_GBUFFER_DEPTH);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
  glEnable(GL_SCISSOR_TEST);
  const std::vector<int> reflectors = passes.scene().scene().reflectorInstances();
  for (size_t k = 0; k < reflectors.size(); ++k) {
    const ivec4 r = rectangles[k];
    if (r.x >= r.z || r.y >= r.w) continue;
    glScissor(r.x, r.y, r.z - r.x, r.w - r.y);
    program.set("u_gbuffer_reflector", int(k) + 1);
    if (options.each) options.each(reflectors[k]);
    passes.drawFullscreen(program);
  }
  glDisable(GL_SCISSOR_TEST);
  glColorMaski(0, GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void ReflectorGBuffer::drawTriangles(const FrameTarget& target, ScenePasses& passes,
                                     const View& view, const FrameSettings& settings,
                                     const gpu::Program& program, const ShadeOptions& options,
                                     const std::vector<ivec4>& rectangles) {
  // Over the depth drawn before, on the same vertex shader (invariant): the visible pixels
  // alone pass GL_LEQUAL. The colour (its alpha the eye distance) and the ids are written whole,
  // as a pass over the triangles writes them.
  target.bind();
  passes.begin(view, settings);
  DepthState visible(GL_LEQUAL, false);
  const std::vector<int> reflectors = passes.scene().scene().reflectorInstances();
  for (size_t k = 0; k < reflectors.size(); ++k) {
    const ivec4 r = rectangles[k];
    if (r.x >= r.z || r.y >= r.w) continue;
    if (options.each) options.each(reflectors[k]);
    passes.drawReflectorInstances(program, std::span<const int>(&reflectors[k], 1));
  }
}

bool screenPassPays(size_t triangles, const ivec4& rectangle) {
  const double area = double(std::max(rectangle.z - rectangle.x, 0)) *
                      double(std::max(rectangle.w - rectangle.y, 0));
  return area <= kScreenPassPixelsPerTriangle * double(triangles);
}

ivec4 screenRectangle(const Bounds3& bounds, const View& view) {
  const ivec2 size = view.size();
  const ivec4 whole(0, 0, size.x, size.y);
  if (bounds.empty()) return ivec4(0);
  const mat4 m = view.viewProjection();
  vec2 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
  for (int c = 0; c < 8; ++c) {
    const vec3 p((c & 1) ? bounds.hi.x : bounds.lo.x, (c & 2) ? bounds.hi.y : bounds.lo.y,
                 (c & 4) ? bounds.hi.z : bounds.lo.z);
    const vec4 clip = m * vec4(p, 1.0f);
    if (clip.w <= 1e-6f) return whole;  // reaches behind the eye: its projection is unbounded
    const vec2 ndc = vec2(clip) / clip.w;
    lo = glm::min(lo, ndc);
    hi = glm::max(hi, ndc);
  }
  const vec2 px_lo = (lo * 0.5f + 0.5f) * vec2(size), px_hi = (hi * 0.5f + 0.5f) * vec2(size);
  // A pixel of margin, then out to even coordinates: whole quads.
  ivec2 a = ivec2(glm::floor(px_lo)) - 1, b = ivec2(glm::ceil(px_hi)) + 1;
  a = glm::max(a - (a & 1), ivec2(0));
  b = glm::min(b + (b & 1), size);
  return ivec4(a, b);
}

}  // namespace mirage
