// Depth alone: a pre-pass that leaves the nearest depth for a later pass under GL_LEQUAL. No
// outputs and no side effects, so a rasteriser may skip shading altogether (llvmpipe does: on
// teapots4 this pre-pass costs less than one through the base-colour program with colour writes
// masked, which still shades).
void main() {}
