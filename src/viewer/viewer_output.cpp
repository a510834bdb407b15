#include "viewer/viewer_output.h"

#include <cmath>
#include <limits>

#include "eval/metrics.h"
#include "gpu/feedback_check.h"

namespace mirage {

const char* truthModeName(TruthMode mode) {
  return choiceName<TruthMode>(kTruthModes, mode);
}

ViewerOutput::ViewerOutput()
    : plain_(gpu::Program::graphics("render/shaders/fullscreen.vert", "viewer/display.frag")),
      with_truth_(gpu::Program::graphics("render/shaders/fullscreen.vert", "viewer/display.frag",
                                         {"VIEWER_TRUTH 1"})),
      vao_(gpu::createVertexArray()) {}

void ViewerOutput::setTruth(const TruthImage& truth) {
  const ivec2 size(truth.color.width(), truth.color.height());
  if (truth_.size() != size) {
    truth_ = gpu::Texture::create2D(GL_RGBA32F, size.x, size.y);
    truth_.setFilter(GL_LINEAR, GL_LINEAR);
    truth_.setWrap(GL_CLAMP_TO_EDGE);
  }
  Image rows = truth.color;
  rows.flipVertically();
  truth_.upload(0, GL_RGBA, GL_FLOAT, rows.data());
  has_truth_ = true;
}

void ViewerOutput::draw(const gpu::Texture& frame, ivec2 size, const OutputSettings& s) const {
  glViewport(0, 0, size.x, size.y);
  glDisable(GL_DEPTH_TEST);
  frame.bind(0);
  const bool truth = has_truth_ && (s.truth != TruthMode::kOff || s.heatmap);
  if (truth) truth_.bind(1);
  float split = float(size.x) + 1.0f;  // the method everywhere
  if (s.truth == TruthMode::kSplit) split = s.split * float(size.x);
  if (s.truth == TruthMode::kFlip) split = -1.0f;  // the reference everywhere
  const gpu::Program& program = truth ? with_truth_ : plain_;
  program.set("u_exposure", s.display.exposure);
  program.set("u_tonemap", int(s.display.tonemap));
  program.set("u_ssaa", std::max(s.ssaa, 1));
  if (truth) {
    program.set("u_split", split);
    program.set("u_line", s.truth == TruthMode::kSplit ? 1 : 0);
    program.set("u_heatmap", s.heatmap ? 1 : 0);
    program.set("u_heat_max", std::max(s.heat_max, 1e-4f));
    program.set("u_size", vec2(size));
  }
  program.use();
  glBindVertexArray(vao_.id());
  gpu::checkFeedback();
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

double truthPsnr(const RenderedFrame& frame, const TruthImage& truth,
                 const DisplaySettings& display) {
  const int w = truth.color.width(), h = truth.color.height();
  const int fw = frame.color.width(), fh = frame.color.height();
  if (w <= 0 || h <= 0 || fw <= 0 || fh <= 0) return std::numeric_limits<double>::quiet_NaN();
  // Each reference pixel covers the frame pixels whose centres fall inside it.
  Image down(w, h);
  for (int y = 0; y < h; ++y) {
    const int y0 = y * fh / h, y1 = std::max((y + 1) * fh / h, y0 + 1);
    for (int x = 0; x < w; ++x) {
      const int x0 = x * fw / w, x1 = std::max((x + 1) * fw / w, x0 + 1);
      vec4 sum(0.0f);
      for (int v = y0; v < y1; ++v)
        for (int u = x0; u < x1; ++u) sum += frame.color(u, v);
      down(x, y) = sum / float((x1 - x0) * (y1 - y0));
    }
  }
  if (countNonZero(truth.ids) == 0) return std::numeric_limits<double>::quiet_NaN();
  return psnrFromMse(
      meanSquaredError(toDisplay(down, display), toDisplay(truth.color, display), &truth.ids));
}

}  // namespace mirage
