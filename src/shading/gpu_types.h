// Structs shared by the C++ host code and the shaders: uniform blocks (std140) and storage
// buffers (std430). Only vec4/ivec4/mat4 members, so the two layouts agree with C++'s; the C++
// side static_asserts every size (bottom of the file). Binding points are #defines for both.
#ifndef MIRAGE_SHADING_GPU_TYPES_H
#define MIRAGE_SHADING_GPU_TYPES_H

#include "shading/glsl_compat.h"

// Buffer binding points.
#define MIRAGE_BIND_FRAME 0      // UBO FrameData
#define MIRAGE_BIND_INSTANCES 1  // SSBO InstanceData[]
#define MIRAGE_BIND_MATERIALS 2  // SSBO MaterialData[]
#define MIRAGE_BIND_METHOD 3     // UBO owned by the method being run
#define MIRAGE_BIND_METHOD_SSBO 4
// Texture units.
#define MIRAGE_UNIT_ENVIRONMENT 0  // the scene's distant environment (cube map)
#define MIRAGE_UNIT_ALBEDO 1       // the drawn instance's albedo texture
#define MIRAGE_UNIT_NORMAL_MAP 2   // the drawn instance's normal map
#define MIRAGE_UNIT_METHOD 4       // first unit a method may use
// The reflector G-buffer's (render/reflector_gbuffer.h), for the screen-space reflector passes;
// above every method's units.
#define MIRAGE_UNIT_GBUFFER_NORMAL 14  // rgba32f: octahedral normal, material + 1, reflector id
#define MIRAGE_UNIT_GBUFFER_DEPTH 15   // the frame's depth

// Material kinds (MaterialData.kind.x).
#define MIRAGE_MATERIAL_DIFFUSE 0
#define MIRAGE_MATERIAL_REFLECTOR 1

// Tone-mapping operators (shading/tonemap.h).
#define MIRAGE_TONEMAP_CLAMP 0
#define MIRAGE_TONEMAP_REINHARD 1
#define MIRAGE_TONEMAP_ACES 2

SHARED_BEGIN

// Everything a shader needs to know about the frame (one UBO, updated once per view).
struct FrameData {
  mat4 view_proj;
  mat4 inv_view_proj;
  vec4 eye;          // xyz: eye position; w: scene time in seconds
  vec4 light_dir;    // xyz: unit direction towards the light
  vec4 light_color;  // rgb: directional light radiance
  vec4 ambient;      // rgb: ambient light
  vec4 viewport;     // x, y: size in pixels; z: tan(fov_y / 2); w: environment max mip level
  ivec4 options;     // x: reflection order K; y: mip-mapped lookups on (1) / off (0)
  vec4 env;          // x: environment intensity; yzw: unused
};

// One drawn instance (SSBO array indexed by the per-draw instance index).
struct InstanceData {
  mat4 model;
  mat4 normal_matrix;  // inverse transpose of the model's 3x3, padded
  ivec4 ids;           // x: material; y: reflector id (1-based, 0 = not a reflector); z: mesh
};

// One material. Diffuse: albedo (or checker), optional texture. Reflector: base colour, tint,
// reflectivity, Fresnel f0, distance attenuation range, optional normal map.
struct MaterialData {
  vec4 albedo;   // rgb: diffuse albedo or reflector base colour
  vec4 tint;     // rgb: reflector tint; w: reflectivity in [0, 1]
  vec4 params;   // x: Fresnel f0; y: attenuation range (0 = off)
  vec4 checker;  // rgb: second checker colour; w: checker cells per uv unit (0 = no checker)
  ivec4 kind;    // x: MIRAGE_MATERIAL_*; y: albedo texture (-1 none); z: normal map (-1 none)
};

// One reflection probe of a scene's "probes" (scene/probes.h) as the blended probe lookup reads
// it (render/shaders/probe_lookup.glsl, PROBE_BLEND), in blend order (shading/probe_blend.h).
struct ProbeVolumeData {
  vec4 position;      // xyz: where the probe was captured; w: its cube's layer
  vec4 influence_lo;  // xyz: the influence box's min, or the sphere's centre; w: blend distance
  vec4 influence_hi;  // xyz: the influence box's max; w: the sphere's radius (0: a box)
  vec4 proxy_lo;      // xyz: the proxy box's min, or the sphere's centre
  vec4 proxy_hi;      // xyz: the proxy box's max; w: the sphere's radius (0: a box)
};

SHARED_END

#ifndef MIRAGE_GLSL
static_assert(sizeof(mirage::shading::FrameData) == 2 * 64 + 7 * 16, "FrameData layout");
static_assert(sizeof(mirage::shading::InstanceData) == 2 * 64 + 16, "InstanceData layout");
static_assert(sizeof(mirage::shading::MaterialData) == 5 * 16, "MaterialData layout");
static_assert(sizeof(mirage::shading::ProbeVolumeData) == 5 * 16, "ProbeVolumeData layout");
#endif

#endif  // MIRAGE_SHADING_GPU_TYPES_H
