// OpenGL entry points for mirage: libepoxy resolves them for EGL and GLX contexts alike.
#pragma once

#include <epoxy/gl.h>
