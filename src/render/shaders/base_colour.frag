// Reflectors shown in their base colour, no reflection: the `none` method's frame, and what
// every method draws for the reflectors it does not reflect (render/base_colour.h).
#define MIRAGE_NO_REFLECTION 1
#include "render/shaders/reflector.glsl"
