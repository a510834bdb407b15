// Method `ssr`: the G-buffer pass for reflectors — their base colour (a screen-space hit on a
// reflector shows what order 1 shows there) and their normal. Diffuse surfaces are drawn by
// render/shaders/diffuse.frag with the same MIRAGE_GBUFFER define.
#define MIRAGE_NO_REFLECTION 1
#include "render/shaders/reflector.glsl"
