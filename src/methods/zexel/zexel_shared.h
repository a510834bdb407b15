// The zexel method's GPU data as the shaders and the C++ code see it: bindings, and the cells the
// warp leaves per frame pixel (zexel_splat_shared.h: the nearest zexel that landed in the pixel —
// its distance's float bits first, which order like the floats for positive values, so atomicMin
// keeps the nearest — where it landed, its splat, colour and kernel).
#ifndef MIRAGE_METHODS_ZEXEL_ZEXEL_SHARED_H
#define MIRAGE_METHODS_ZEXEL_ZEXEL_SHARED_H

#include "shading/glsl_compat.h"

#define MIRAGE_BIND_ZEXEL_KEYS 4        // uint a cell: its first word's x (the only one cleared)
#define MIRAGE_BIND_ZEXEL_CELLS 5       // uvec4[2] a cell: its words but the key
#define MIRAGE_BIND_ZEXEL_COUNTERS 6    // MIRAGE_ZEXEL_COUNTERS, below, in counter slots
#define MIRAGE_BIND_ZEXEL_TILES 7       // uvec2 per tile warped: its coordinates, its spacing
#define MIRAGE_BIND_ZEXEL_FAR 8         // float per curved reflector's cube: its farthest distance
#define MIRAGE_UNIT_ZEXEL_MAPS 4        // sampler2DArray: every map of the mirror, mip levels
#define MIRAGE_UNIT_ZEXEL_KEYS 5        // usamplerBuffer r32ui: the keys, as the mirror reads them
#define MIRAGE_UNIT_ZEXEL_CELLS 6       // usamplerBuffer rgba32ui: the cells, likewise
#define MIRAGE_UNIT_ZEXEL_RESOLVED 7    // samplerBuffer rgba32f: a resolved texel a mirror pixel
#define MIRAGE_UNIT_ZEXEL_DISTANCES 5   // samplerCubeArray r32f: the curved search's pyramid
#define MIRAGE_UNIT_ZEXEL_REDUCED 6     // samplerCubeArray r32f: its build's reductions M_L
#define MIRAGE_IMAGE_ZEXEL_HISTORY 0    // rgba32f: the mirror's last image (the no-clear option)
#define MIRAGE_IMAGE_ZEXEL_LEVEL_IN 1   // the pyramid build: the finer level
#define MIRAGE_IMAGE_ZEXEL_LEVEL_OUT 2  // ... and the coarser one it writes
#define MIRAGE_IMAGE_ZEXEL_RESOLVED 3   // imageBuffer rgba32f: the resolve's output (zexel_resolve)
#define MIRAGE_IMAGE_ZEXEL_REDUCED 3    // the distance pyramid's build: level 0 of the reductions

// The counters: the mirror pixels exposed (the visible ones are counted by a samples query); the
// curved reflectors' pixels searched and the map reads their searches made.
#define MIRAGE_ZEXEL_COUNTERS 3
#define MIRAGE_ZEXEL_COUNT_EXPOSED 0
#define MIRAGE_ZEXEL_COUNT_CURVED_RAYS 1
#define MIRAGE_ZEXEL_COUNT_CURVED_READS 2

#define MIRAGE_ZEXEL_GROUP 64           // invocations per warp work group (one zexel each)
#define MIRAGE_ZEXEL_RESOLVE_GROUP 8    // the resolve's work groups: 8 x 8 invocations
#define MIRAGE_ZEXEL_MAX_SPLAT 8        // the largest magnification-sized splat, in pixels
#define MIRAGE_ZEXEL_EMPTY 0xFFFFFFFFu  // a pixel no zexel reached (an exposure)

#endif  // MIRAGE_METHODS_ZEXEL_ZEXEL_SHARED_H
