// Method `none`: reflectors show their base colour.
#define MIRAGE_NO_REFLECTION 1
#include "render/shaders/reflector.glsl"
