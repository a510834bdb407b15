#include "gpu/object_count.h"

#include <algorithm>

#include <fmt/format.h>

#include "gpu/handle.h"

namespace mirage::gpu {

std::string ObjectCounts::text() const {
  return fmt::format(
      "buffers {}, textures {}, framebuffers {}, vertex arrays {}, programs {}, shaders {}, "
      "queries {}",
      buffers, textures, framebuffers, vertex_arrays, programs, shaders, queries);
}

ObjectCounts liveHandles() {
  ObjectCounts c;
  c.buffers = Handle<BufferTraits>::live();
  c.textures = Handle<TextureTraits>::live();
  c.framebuffers = Handle<FramebufferTraits>::live();
  c.vertex_arrays = Handle<VertexArrayTraits>::live();
  c.programs = Handle<ProgramTraits>::live();
  c.shaders = Handle<ShaderTraits>::live();
  c.queries = Handle<QueryTraits>::live();
  return c;
}

ObjectCounts glObjects(unsigned at_least) {
  ObjectCounts c;
  const GLuint last = std::max<GLuint>(largestHandleName(), at_least);
  for (GLuint name = 1; name <= last; ++name) {
    c.buffers += glIsBuffer(name) == GL_TRUE;
    c.textures += glIsTexture(name) == GL_TRUE;
    c.framebuffers += glIsFramebuffer(name) == GL_TRUE;
    c.vertex_arrays += glIsVertexArray(name) == GL_TRUE;
    c.programs += glIsProgram(name) == GL_TRUE;
    c.shaders += glIsShader(name) == GL_TRUE;
    c.queries += glIsQuery(name) == GL_TRUE;
  }
  return c;
}

}  // namespace mirage::gpu
