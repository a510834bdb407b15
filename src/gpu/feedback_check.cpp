#include "gpu/feedback_check.h"

#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "core/error.h"
#include "gpu/context.h"
#include "gpu/gl.h"

namespace mirage::gpu {
namespace {

std::atomic<bool>& enabled() {
  static std::atomic<bool> on{debugSwitch("MIRAGE_GL_CHECK_FEEDBACK")};
  return on;
}

// The texture binding a sampler type reads, or nullopt for a type that is not a sampler.
std::optional<GLenum> samplerBinding(GLenum type) {
  switch (type) {
    case GL_SAMPLER_2D:
    case GL_SAMPLER_2D_SHADOW:
    case GL_INT_SAMPLER_2D:
    case GL_UNSIGNED_INT_SAMPLER_2D:
      return GL_TEXTURE_BINDING_2D;
    case GL_SAMPLER_2D_ARRAY:
    case GL_SAMPLER_2D_ARRAY_SHADOW:
    case GL_INT_SAMPLER_2D_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
      return GL_TEXTURE_BINDING_2D_ARRAY;
    case GL_SAMPLER_CUBE:
    case GL_SAMPLER_CUBE_SHADOW:
    case GL_INT_SAMPLER_CUBE:
    case GL_UNSIGNED_INT_SAMPLER_CUBE:
      return GL_TEXTURE_BINDING_CUBE_MAP;
    case GL_SAMPLER_CUBE_MAP_ARRAY:
    case GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW:
    case GL_INT_SAMPLER_CUBE_MAP_ARRAY:
    case GL_UNSIGNED_INT_SAMPLER_CUBE_MAP_ARRAY:
      return GL_TEXTURE_BINDING_CUBE_MAP_ARRAY;
    case GL_SAMPLER_3D:
    case GL_INT_SAMPLER_3D:
    case GL_UNSIGNED_INT_SAMPLER_3D:
      return GL_TEXTURE_BINDING_3D;
    default:
      return std::nullopt;
  }
}

// A texture a sampler of the program reads: its name, unit and the sampler's name.
struct SampledTexture {
  GLuint texture;
  GLint unit;
  std::string sampler;
};

GLuint textureOnUnit(GLint unit, GLenum binding) {
  GLint active = 0, texture = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  glActiveTexture(GLenum(GL_TEXTURE0 + unit));
  glGetIntegerv(binding, &texture);
  glActiveTexture(GLenum(active));
  return GLuint(texture);
}

std::vector<SampledTexture> sampledTextures(GLuint program) {
  std::vector<SampledTexture> out;
  GLint count = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  for (GLint i = 0; i < count; ++i) {
    char name[256];
    GLint size = 0;
    GLenum type = 0;
    glGetActiveUniform(program, GLuint(i), sizeof(name), nullptr, &size, &type, name);
    const std::optional<GLenum> binding = samplerBinding(type);
    if (!binding) continue;
    std::string base = name;
    if (const size_t bracket = base.find('['); bracket != std::string::npos) base.resize(bracket);
    for (GLint element = 0; element < size; ++element) {
      const std::string element_name = size > 1 ? base + "[" + std::to_string(element) + "]" : base;
      const GLint location = glGetUniformLocation(program, element_name.c_str());
      if (location < 0) continue;
      GLint unit = 0;
      glGetUniformiv(program, location, &unit);
      if (const GLuint texture = textureOnUnit(unit, *binding))
        out.push_back({texture, unit, element_name});
    }
  }
  return out;
}

// Whether a sampler on `unit` can read `level` of `texture` (the levels its filter and level
// range allow; a sampler object bound to the unit overrides the texture's filter).
bool canSampleLevel(GLuint texture, GLint unit, GLint level) {
  GLint base = 0, max_level = 0, min_filter = 0, sampler = 0;
  glGetTextureParameteriv(texture, GL_TEXTURE_BASE_LEVEL, &base);
  glGetTextureParameteriv(texture, GL_TEXTURE_MAX_LEVEL, &max_level);
  glGetIntegeri_v(GL_SAMPLER_BINDING, GLuint(unit), &sampler);
  if (sampler != 0)
    glGetSamplerParameteriv(GLuint(sampler), GL_TEXTURE_MIN_FILTER, &min_filter);
  else
    glGetTextureParameteriv(texture, GL_TEXTURE_MIN_FILTER, &min_filter);
  if (min_filter == GL_NEAREST || min_filter == GL_LINEAR) return level == base;
  return level >= base && level <= max_level;
}

struct Attachment {
  GLenum point;
  GLuint texture;
  GLint level;
};

std::vector<Attachment> textureAttachments(GLuint framebuffer) {
  GLint colors = 0;
  glGetIntegerv(GL_MAX_COLOR_ATTACHMENTS, &colors);
  std::vector<GLenum> points{GL_DEPTH_ATTACHMENT, GL_STENCIL_ATTACHMENT};
  for (GLint i = 0; i < colors; ++i) points.push_back(GLenum(GL_COLOR_ATTACHMENT0 + i));
  std::vector<Attachment> out;
  for (GLenum point : points) {
    GLint type = GL_NONE, name = 0, level = 0;
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, point,
                                               GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_TEXTURE) continue;
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, point,
                                               GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    glGetNamedFramebufferAttachmentParameteriv(framebuffer, point,
                                               GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
    out.push_back({point, GLuint(name), level});
  }
  return out;
}

std::string attachmentName(GLenum point) {
  if (point == GL_DEPTH_ATTACHMENT) return "the depth attachment";
  if (point == GL_STENCIL_ATTACHMENT) return "the stencil attachment";
  return "colour attachment " + std::to_string(point - GL_COLOR_ATTACHMENT0);
}

}  // namespace

bool feedbackChecks() {
  return enabled().load(std::memory_order_relaxed);
}
void setFeedbackChecks(bool on) {
  enabled().store(on, std::memory_order_relaxed);
}

void checkFeedback() {
  if (!feedbackChecks()) return;
  GLint framebuffer = 0, program = 0;
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  if (framebuffer == 0 || program == 0) return;
  const std::vector<Attachment> attachments = textureAttachments(GLuint(framebuffer));
  for (const SampledTexture& sampled : sampledTextures(GLuint(program)))
    for (const Attachment& a : attachments)
      if (a.texture == sampled.texture && canSampleLevel(a.texture, sampled.unit, a.level))
        throwRuntime(
            "OpenGL feedback loop: sampler '{}' (unit {}) of program {} reads texture {}, level "
            "{} of which is {} of the bound draw framebuffer {}",
            sampled.sampler, sampled.unit, program, a.texture, a.level, attachmentName(a.point),
            framebuffer);
}

}  // namespace mirage::gpu
