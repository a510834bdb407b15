// The depth test a pass runs under, for as long as the guard lives; then the state every pass
// starts from (ScenePasses::begin): GL_LESS with depth writes on. For passes over surfaces whose
// depth is in the buffer already (GL_EQUAL, GL_LEQUAL on the same invariant vertex shader).
#pragma once

#include "gpu/gl.h"

namespace mirage {

class DepthState {
 public:
  DepthState(GLenum func, bool write) {
    glDepthFunc(func);
    glDepthMask(write ? GL_TRUE : GL_FALSE);
  }
  ~DepthState() {
    glDepthMask(GL_TRUE);
    glDepthFunc(GL_LESS);
  }
  DepthState(const DepthState&) = delete;
  DepthState& operator=(const DepthState&) = delete;
};

}  // namespace mirage
