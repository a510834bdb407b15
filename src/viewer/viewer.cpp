#include "viewer/viewer.h"

#include <memory>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <spdlog/spdlog.h>

#include "core/timer.h"
#include "gpu/program.h"
#include "gpu/window_context.h"
#include "viewer/orbit_camera.h"

namespace mirage {

namespace {

// Dear ImGui bound to one window for its lifetime.
class ImGuiSession {
 public:
  explicit ImGuiSession(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini next to the user's files
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450");
  }
  ~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  ImGuiSession(const ImGuiSession&) = delete;
  ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// The renderer and the method at the window's framebuffer size; remade when either changes.
struct Stage {
  std::unique_ptr<FrameRenderer> renderer;
  std::unique_ptr<Method> method;
  std::string method_name;
};

class Viewer {
 public:
  Viewer(const Scene& scene, const ViewerOptions& options)
      : scene_(scene),
        options_(options),
        window_(gpu::WindowOptions{options.size, "mirage — " + scene.name, true, options.vsync}),
        imgui_(window_.window()),
        camera_(options.camera),
        display_(gpu::Program::graphics("render/shaders/fullscreen.vert", "viewer/display.frag")),
        vao_(gpu::createVertexArray()),
        method_name_(options.method) {}

  int run() {
    for (int frame = 0; !window_.shouldClose(); ++frame) {
      glfwPollEvents();
      handleInput();
      const ivec2 size = window_.framebufferSize();
      if (size.x <= 0 || size.y <= 0) continue;  // minimised
      ensureStage(size);
      Stopwatch watch;
      stage_.renderer->render(*stage_.method, View(camera_.desc(), size), options_.time,
                              options_.settings);
      glFinish();
      frame_ms_ = 0.9 * frame_ms_ + 0.1 * watch.ms();
      present(size);
      const bool last = options_.frames > 0 && frame + 1 >= options_.frames;
      if (last && !options_.screenshot.empty()) screenshot(size);
      drawPanel();
      window_.swapBuffers();
      if (last) return 0;
    }
    return 0;
  }

 private:
  void ensureStage(ivec2 size) {
    if (!stage_.renderer || stage_.renderer->size() != size) {
      stage_ = Stage{};
      stage_.renderer = std::make_unique<FrameRenderer>(scene_, size);
    }
    if (!stage_.method || stage_.method_name != method_name_) {
      stage_.method =
          stage_.renderer->createMethod(method_name_, options_.params, options_.settings);
      stage_.method_name = method_name_;
    }
  }

  void handleInput() {
    const ImGuiIO& io = ImGui::GetIO();
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window_.window(), &x, &y);
    const vec2 cursor{float(x), float(y)};
    const vec2 delta = cursor - last_cursor_;
    last_cursor_ = cursor;
    if (!io.WantCaptureMouse) {
      GLFWwindow* w = window_.window();
      if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS) camera_.orbit(delta);
      if (glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS ||
          glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS)
        camera_.pan(delta, float(window_.framebufferSize().y));
      if (io.MouseWheel != 0.0f) camera_.dolly(io.MouseWheel);
    }
    const bool r = glfwGetKey(window_.window(), GLFW_KEY_R) == GLFW_PRESS;
    if (r && !r_was_down_ && !io.WantCaptureKeyboard) camera_.reset(options_.camera);
    r_was_down_ = r;
  }

  // The frame through the display transform into the window.
  void present(ivec2 size) {
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, size.x, size.y);
    glDisable(GL_DEPTH_TEST);
    stage_.renderer->target().color().bind(0);
    display_.set("u_exposure", options_.display.exposure);
    display_.set("u_tonemap", int(options_.display.tonemap));
    display_.use();
    glBindVertexArray(vao_.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }

  // The last frame: a .png is what the window shows (before the panel is drawn over it), read
  // back from the window's framebuffer — the display shader's output; an .exr the linear frame.
  void screenshot(ivec2 size) {
    if (!options_.screenshot.ends_with(".png")) {
      writeImage(options_.screenshot, stage_.renderer->read().color, options_.display);
      return;
    }
    Image shown(size.x, size.y);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_FLOAT, shown.data());
    shown.flipVertically();
    writePng(options_.screenshot, shown);
  }

  void drawPanel() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImGui::Begin("mirage");
    ImGui::Text("%s", scene_.name.c_str());
    if (ImGui::BeginCombo("method", method_name_.c_str())) {
      for (const std::string& name : methodNames())
        if (ImGui::Selectable(name.c_str(), name == method_name_)) method_name_ = name;
      ImGui::EndCombo();
    }
    ImGui::SliderInt("order K", &options_.settings.order, 0, 16);
    ImGui::Text("%.1f ms (%.0f fps)", frame_ms_, frame_ms_ > 0.0 ? 1000.0 / frame_ms_ : 0.0);
    for (const auto& [name, value] : stage_.method->stats())
      ImGui::Text("%s: %g", name.c_str(), value);
    ImGui::TextDisabled("left drag: orbit, right drag: pan, wheel: dolly, R: reset");
    ImGui::End();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }

  const Scene& scene_;
  ViewerOptions options_;
  gpu::WindowContext window_;
  ImGuiSession imgui_;
  OrbitCamera camera_;
  gpu::Program display_;
  gpu::Handle<gpu::VertexArrayTraits> vao_;
  std::string method_name_;
  Stage stage_;
  vec2 last_cursor_{0.0f};
  bool r_was_down_ = false;
  double frame_ms_ = 0.0;
};

}  // namespace

int runViewer(const Scene& scene, const ViewerOptions& options) {
  Viewer viewer(scene, options);
  return viewer.run();
}

}  // namespace mirage
