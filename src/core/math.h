// The math vocabulary of mirage: glm types, used alike by the C++ code and, through
// shading/glsl_compat.h, by the headers shared with the shaders.
#pragma once

#define GLM_FORCE_XYZW_ONLY
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <limits>

namespace mirage {

using glm::ivec2;
using glm::ivec3;
using glm::ivec4;
using glm::mat3;
using glm::mat4;
using glm::quat;
using glm::uvec2;
using glm::uvec3;
using glm::uvec4;
using glm::vec2;
using glm::vec3;
using glm::vec4;

inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr float kInfinity = std::numeric_limits<float>::infinity();

inline float radians(float degrees) {
  return degrees * (kPi / 180.0f);
}
inline float degrees(float radians) {
  return radians * (180.0f / kPi);
}

inline bool isFinite(const vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Transforms a point / a direction by an affine matrix.
inline vec3 transformPoint(const mat4& m, const vec3& p) {
  return vec3(m * vec4(p, 1.0f));
}
inline vec3 transformVector(const mat4& m, const vec3& v) {
  return vec3(m * vec4(v, 0.0f));
}
// Normals transform with the inverse transpose of the upper 3x3.
inline mat3 normalMatrix(const mat4& m) {
  return glm::transpose(glm::inverse(mat3(m)));
}

}  // namespace mirage
