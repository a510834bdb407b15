// Declarations every scene shader shares: the frame uniforms, instance and material buffers and
// the environment. The structs come from shading/gpu_types.h, the same header the C++ code uses.
#include "shading/gpu_types.h"
#include "shading/shading.h"

layout(std140, binding = MIRAGE_BIND_FRAME) uniform FrameBlock { FrameData frame; };
layout(std430, binding = MIRAGE_BIND_INSTANCES) readonly buffer InstanceBlock {
  InstanceData instances[];
};
layout(std430, binding = MIRAGE_BIND_MATERIALS) readonly buffer MaterialBlock {
  MaterialData materials[];
};
layout(binding = MIRAGE_UNIT_ENVIRONMENT) uniform samplerCube u_environment;
