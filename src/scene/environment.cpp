#include "scene/environment.h"

#include <Imath/half.h>
#include <tbb/parallel_for.h>

#include "core/error.h"
#include "scene/scene.h"
#include "shading/cubemap.h"
#include "shading/sky.h"

namespace mirage {

namespace {

constexpr int kSkyFaceSize = 256;

vec4 bilinearEquirect(const Image& img, vec2 uv) {
  float x = uv.x * float(img.width()) - 0.5f, y = uv.y * float(img.height()) - 0.5f;
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float fx = x - float(x0), fy = y - float(y0);
  auto at = [&](int xi, int yi) {
    xi = ((xi % img.width()) + img.width()) % img.width();  // wraps around in longitude
    yi = std::clamp(yi, 0, img.height() - 1);
    return img(xi, yi);
  };
  return glm::mix(glm::mix(at(x0, y0), at(x0 + 1, y0), fx),
                  glm::mix(at(x0, y0 + 1), at(x0 + 1, y0 + 1), fx), fy);
}

}  // namespace

vec2 equirectUv(const vec3& d) {
  float u = 0.5f + std::atan2(d.x, -d.z) / (2.0f * kPi);
  float v = std::acos(std::clamp(d.y, -1.0f, 1.0f)) / kPi;
  return {u, v};
}

template <typename F>
EnvironmentMap EnvironmentMap::fromFunction(int face_size, F radiance) {
  if (face_size < 1 || face_size > 8192)
    throwInput("environment cube size {} is outside the allowed range 1..8192", face_size);
  EnvironmentMap env;
  env.size_ = face_size;
  for (int f = 0; f < 6; ++f) {
    auto& pixels = env.faces_[size_t(f)];
    pixels.resize(size_t(face_size) * size_t(face_size));
    tbb::parallel_for(0, face_size, [&](int y) {
      for (int x = 0; x < face_size; ++x) {
        vec2 st((float(x) + 0.5f) / float(face_size), (float(y) + 0.5f) / float(face_size));
        vec3 d = glm::normalize(shading::cube_direction(f, st));
        pixels[size_t(y * face_size + x)] = vec4(radiance(d), 1.0f);
      }
    });
  }
  return env;
}

void EnvironmentMap::finish(float intensity, float clamp) {
  for (auto& face : faces_)
    for (vec4& p : face) {
      vec3 c = vec3(p) * intensity;
      if (clamp > 0.0f) c = glm::min(c, vec3(clamp));
      for (int i = 0; i < 3; ++i) c[i] = float(half(c[i]));
      p = vec4(c, 1.0f);
    }
}

EnvironmentMap EnvironmentMap::sky(const Light& light, int face_size) {
  return fromFunction(face_size, [&](const vec3& d) {
    return shading::procedural_sky(d, light.direction, light.color);
  });
}

EnvironmentMap EnvironmentMap::equirect(const Image& image, int face_size, float rotation_degrees) {
  if (image.empty()) throwInput("environment image is empty");
  mat3 rotation = mat3(glm::rotate(mat4(1.0f), radians(-rotation_degrees), vec3(0, 1, 0)));
  return fromFunction(face_size, [&](const vec3& d) {
    return vec3(bilinearEquirect(image, equirectUv(rotation * d)));
  });
}

EnvironmentMap EnvironmentMap::forScene(const Scene& scene) {
  const EnvironmentDesc& desc = scene.environment;
  EnvironmentMap env;
  if (desc.image.empty()) {
    env = sky(scene.lightAt(0.0f), desc.cube_size > 0 ? desc.cube_size : kSkyFaceSize);
  } else {
    Image image = readImage(desc.image, Encoding::kSrgb);
    // A face a quarter of the panorama's width keeps its equatorial resolution.
    int size = desc.cube_size > 0 ? desc.cube_size : std::clamp(image.width() / 4, 16, 2048);
    env = equirect(image, size, desc.rotation_degrees);
  }
  env.finish(desc.intensity, desc.clamp);
  return env;
}

vec3 EnvironmentMap::sample(const vec3& d) const {
  vec2 st;
  int face = shading::cube_face_st(d, st);
  float x = st.x * float(size_) - 0.5f, y = st.y * float(size_) - 0.5f;
  int x0 = int(std::floor(x)), y0 = int(std::floor(y));
  float fx = x - float(x0), fy = y - float(y0);
  // Taps outside the face are taken from the neighbouring face, as GL's seamless filtering does.
  auto tap = [&](int xi, int yi) {
    if (xi >= 0 && yi >= 0 && xi < size_ && yi < size_) return texel(face, xi, yi);
    vec2 outside((float(xi) + 0.5f) / float(size_), (float(yi) + 0.5f) / float(size_));
    vec2 st2;
    int f2 = shading::cube_face_st(shading::cube_direction(face, outside), st2);
    int x2 = std::clamp(int(st2.x * float(size_)), 0, size_ - 1);
    int y2 = std::clamp(int(st2.y * float(size_)), 0, size_ - 1);
    return texel(f2, x2, y2);
  };
  return glm::mix(glm::mix(tap(x0, y0), tap(x0 + 1, y0), fx),
                  glm::mix(tap(x0, y0 + 1), tap(x0 + 1, y0 + 1), fx), fy);
}

}  // namespace mirage
