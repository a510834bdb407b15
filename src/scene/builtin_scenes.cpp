#include "scene/builtin_scenes.h"

#include "core/error.h"
#include "scene/builtin_scene_parts.h"
#include "scene/procedural.h"

namespace mirage {

void addMainCamera(Scene& s, vec3 position, vec3 target, float fov_y_degrees) {
  CameraDesc cam;
  cam.name = "main";
  cam.position = position;
  cam.target = target;
  cam.fov_y_degrees = fov_y_degrees;
  s.cameras.push_back(cam);
}

void addWalkCamera(Scene& s, std::vector<CameraKey> keys, float fov_y_degrees) {
  CameraDesc cam;
  cam.name = "walk";
  cam.position = keys.front().position;
  cam.target = keys.front().target;
  cam.fov_y_degrees = fov_y_degrees;
  cam.path.keys = std::move(keys);
  s.cameras.push_back(cam);
}

std::vector<vec2> capProfile(float rim_degrees, int rings) {
  std::vector<vec2> profile;  // rim to axis, so that the normals face into the cap
  for (int i = rings; i >= 0; --i) {
    const float t = glm::radians(rim_degrees) * float(i) / float(rings);
    profile.push_back({std::sin(t), 1.0f - std::cos(t)});
  }
  return profile;
}

quat rotationX(float degrees) {
  return glm::angleAxis(radians(degrees), vec3(1, 0, 0));
}
quat rotationY(float degrees) {
  return glm::angleAxis(radians(degrees), vec3(0, 1, 0));
}
quat rotationZ(float degrees) {
  return glm::angleAxis(radians(degrees), vec3(0, 0, 1));
}

namespace {

// A checkerboard floor of `size` units with one-unit cells, at y = 0.
void addCheckerFloor(Scene& s, float size) {
  addObject(s, "floor", procedural::quad(size, size, 1.0f),
            Material::checker("checker", kCheckerLight, kCheckerDark, 1.0f), {});
}

// Keyframes sampling `at` (a transform of u in [0, 1) over one period) 16 times a period,
// looping: a smooth periodic motion for linear/slerp interpolation. Key 0 is at(0), so the scene
// at time 0 is the scene without motion.
template <typename At>
Animation periodic(float period, At at) {
  constexpr int kKeys = 16;
  Animation a;
  a.loop = true;
  for (int k = 0; k <= kKeys; ++k) {
    const float u = float(k) / float(kKeys);
    a.keys.push_back({period * u, at(k == kKeys ? 0.0f : u)});
  }
  return a;
}

Scene sphereOverChecker(const SceneOptions&) {
  Scene s;
  addCheckerFloor(s, 16.0f);
  addBox(s, "red-box", {2.6f, 0.5f, 0.8f}, vec3(0.5f), {0.85f, 0.18f, 0.12f}, 20.0f);
  addBox(s, "green-box", {-2.4f, 0.35f, 1.2f}, vec3(0.35f), {0.2f, 0.7f, 0.25f}, -15.0f);
  addBox(s, "blue-box", {0.6f, 0.75f, -2.6f}, {0.4f, 0.75f, 0.4f}, {0.15f, 0.3f, 0.85f}, 35.0f);
  addBox(s, "yellow-box", {-1.6f, 0.3f, -1.9f}, vec3(0.3f), {0.9f, 0.8f, 0.15f}, 10.0f);
  addObject(s, "mirror-sphere", procedural::sphere(1.0f, 128, 64), Material::mirror("mirror"),
            placeAt({0.0f, 1.25f, 0.0f}));
  addMainCamera(s, {0.0f, 2.6f, 6.5f}, {0.0f, 1.0f, 0.0f}, 45.0f);
  return s;
}

Scene spheres9(const SceneOptions& options) {
  int count = options.reflectors < 0 ? 9 : options.reflectors;
  if (count < 1 || count > 9)
    throwInput("spheres9: --reflectors {} is outside the allowed range 1..9", options.reflectors);
  Scene s;
  addCheckerFloor(s, 24.0f);
  // Diffuse objects between and around the spheres.
  addBox(s, "red-box", {-1.1f, 0.3f, -1.1f}, vec3(0.3f), {0.85f, 0.18f, 0.12f}, 30.0f);
  addBox(s, "green-box", {1.1f, 0.3f, 1.1f}, vec3(0.3f), {0.2f, 0.7f, 0.25f}, -20.0f);
  addBox(s, "blue-box", {1.1f, 0.45f, -1.1f}, {0.25f, 0.45f, 0.25f}, {0.15f, 0.3f, 0.85f}, 10.0f);
  addBox(s, "yellow-box", {-1.1f, 0.25f, 1.1f}, vec3(0.25f), {0.9f, 0.8f, 0.15f}, 45.0f);
  addObject(s, "column", procedural::cylinder(0.25f, 1.6f),
            Material::diffuse("orange", {0.95f, 0.5f, 0.1f}), placeAt({-3.6f, 0.0f, -0.4f}));
  addObject(s, "teapot", procedural::teapotLike(),
            Material::diffuse("purple", {0.55f, 0.25f, 0.7f}),
            placeAt({3.5f, 0.0f, 0.6f}, vec3(1.2f), rotationY(200)));
  int sphere = addMesh(s, procedural::sphere(0.7f, 96, 48));
  int mirror = addMaterial(s, Material::mirror("mirror"));
  // Front row first, as the reflectors are enabled one by one.
  int n = 0;
  for (int row = 2; row >= 0 && n < count; --row)
    for (int col = 0; col < 3 && n < count; ++col, ++n) {
      const vec3 rest(2.2f * float(col - 1), 0.7f, 2.2f * float(row - 1));
      const int sphere_instance =
          addInstance(s, fmt::format("mirror-sphere-{}", n + 1), sphere, mirror, placeAt(rest));
      // Every sphere bobs up to 0.5 above its rest place and back, each with its own period
      // (2 to 3.6 s), so that their reflections of one another change from frame to frame.
      const float period = 2.0f + 0.2f * float(n);
      s.instances[size_t(sphere_instance)].animation = periodic(period, [&](float u) {
        return placeAt(rest + vec3(0.0f, 0.25f * (1.0f - std::cos(2.0f * kPi * u)), 0.0f));
      });
    }
  addMainCamera(s, {0.0f, 5.2f, 8.6f}, {0.0f, 0.4f, 0.0f}, 45.0f);
  return s;
}

// The depth-map impostors' test scene: curved, concave diffuse objects (a teapot, a torus with a
// hole to see through) reflected in a mirror sphere, on a checkerboard.
Scene teapotSphere(const SceneOptions&) {
  Scene s;
  addCheckerFloor(s, 16.0f);
  int teapot = addMesh(s, procedural::teapotLike());
  int purple = addMaterial(s, Material::diffuse("purple", {0.55f, 0.25f, 0.7f}));
  addInstance(s, "teapot", teapot, purple,
              placeAt({-1.25f, 0.0f, 0.3f}, vec3(1.2f), rotationY(-30)));
  Transform standing = placeAt({1.3f, 0.62f, 0.2f});
  // Standing on its rim, its hole facing the sphere.
  standing.rotation = glm::angleAxis(glm::radians(35.0f), vec3(0, 1, 0));
  addObject(s, "torus", procedural::torus(0.45f, 0.16f, 64, 32),
            Material::diffuse("orange", {0.95f, 0.5f, 0.1f}), standing);
  addObject(s, "mirror-sphere", procedural::sphere(1.0f, 128, 64), Material::mirror("mirror"),
            placeAt({0.0f, 1.0f, -0.8f}));
  addMainCamera(s, {0.0f, 1.7f, 4.6f}, {0.0f, 0.8f, -0.3f}, 40.0f);
  return s;
}

Scene mirrorTorus(const SceneOptions&) {
  Scene s;
  addCheckerFloor(s, 16.0f);
  addObject(s, "teapot", procedural::teapotLike(),
            Material::diffuse("purple", {0.55f, 0.25f, 0.7f}),
            placeAt({-1.6f, 0.0f, 0.9f}, vec3(1.2f), rotationY(-30)));
  addObject(s, "mirror-torus", procedural::torus(0.9f, 0.35f, 96, 48), Material::mirror("mirror"),
            placeAt({0.3f, 1.25f, -0.4f}, vec3(1.0f), rotationY(20)));
  addMainCamera(s, {1.2f, 1.9f, 3.0f}, {0.3f, 1.2f, -0.4f}, 40.0f);
  return s;
}

Scene mirrorRoom(const SceneOptions&) {
  Scene s;
  int room = addMesh(s, procedural::box({4.0f, 2.0f, 4.0f}, true));
  int walls = addMaterial(s, Material::checker("walls", kCheckerLight, {0.25f, 0.35f, 0.6f}, 1.0f));
  addInstance(s, "room", room, walls, placeAt({0.0f, 2.0f, 0.0f}));
  int mirror_mesh = addMesh(s, procedural::quad(4.4f, 2.4f));
  int mirror = addMaterial(s, Material::mirror("wall-mirror", vec3(0.05f)));
  addInstance(s, "wall-mirror", mirror_mesh, mirror,
              placeAt({-0.6f, 1.9f, -3.97f}, vec3(1.0f), rotationX(90.0f)));
  int pyramid = addMesh(s, procedural::pyramid(0.45f, 1.0f, true));
  int stone = addMaterial(s, Material::diffuse("stone", {0.75f, 0.72f, 0.65f}));
  addInstance(s, "pyramid", pyramid, stone, placeAt({0.2f, 0.0f, -1.0f}));
  int teapot = addMesh(s, procedural::teapotLike());
  int red = addMaterial(s, Material::diffuse("red", {0.85f, 0.2f, 0.15f}));
  const int teapot_instance = addInstance(s, "teapot", teapot, red,
                                          placeAt({0.2f, 1.0f, -1.0f}, vec3(0.8f), rotationY(-30)));
  // The teapot turns once every 8 s on its pyramid, the box slides 1.2 along the wall and back
  // every 6 s, and the light swings across the room and back every 10 s.
  s.instances[size_t(teapot_instance)].animation = periodic(8.0f, [](float u) {
    return placeAt({0.2f, 1.0f, -1.0f}, vec3(0.8f), rotationY(-30.0f + 360.0f * u));
  });
  addBox(s, "green-box", {-2.2f, 0.4f, -0.2f}, vec3(0.4f), {0.2f, 0.7f, 0.25f}, 25.0f);
  s.instances.back().animation = periodic(6.0f, [](float u) {
    return placeAt({-2.2f, 0.4f, -0.2f + 0.6f * (1.0f - std::cos(2.0f * kPi * u))}, vec3(1.0f),
                   rotationY(25.0f));
  });
  const vec3 light0 = s.light.direction;
  for (int k = 0; k <= 4; ++k) {
    const float swing = radians(70.0f) * std::sin(0.5f * kPi * float(k));  // 0, 70, 0, -70, 0
    s.light.keys.push_back(
        {2.5f * float(k), glm::angleAxis(swing, vec3(0, 1, 0)) * light0, s.light.color});
  }
  s.light.loop = true;
  addMainCamera(s, {2.4f, 2.1f, 3.4f}, {-0.6f, 1.3f, -2.0f}, 55.0f);
  // Six seconds across the room from right to left at eye height, behind the teapot and the box,
  // turning to keep the mirror in view.
  addWalkCamera(s,
                {{0.0f, {2.8f, 1.7f, 3.2f}, {-0.8f, 1.4f, -3.0f}},
                 {2.0f, {1.2f, 1.65f, 2.4f}, {-0.6f, 1.4f, -3.2f}},
                 {4.0f, {-0.9f, 1.7f, 2.2f}, {-0.4f, 1.4f, -3.2f}},
                 {6.0f, {-2.8f, 1.75f, 2.9f}, {0.0f, 1.4f, -3.0f}}},
                55.0f);
  return s;
}

Scene twoMirrors(const SceneOptions&) {
  Scene s;
  addCheckerFloor(s, 16.0f);
  int mirror_mesh = addMesh(s, procedural::quad(7.0f, 2.6f));
  int mirror = addMaterial(s, Material::mirror("mirror", vec3(0.05f), vec3(0.95f)));
  // Quads face +Y; rotate them upright to face each other across x = 0.
  quat face_plus_x = glm::angleAxis(radians(-90.0f), vec3(0, 0, 1)) * rotationY(90.0f);
  quat face_minus_x = glm::angleAxis(radians(90.0f), vec3(0, 0, 1)) * rotationY(90.0f);
  addInstance(s, "mirror-left", mirror_mesh, mirror,
              placeAt({-3.0f, 1.4f, 0.0f}, vec3(1), face_plus_x));
  addInstance(s, "mirror-right", mirror_mesh, mirror,
              placeAt({3.0f, 1.4f, 0.0f}, vec3(1), face_minus_x));
  // Dark frames behind the mirrors, so that their edges show.
  for (float x : {-3.06f, 3.06f})
    addBox(s, x < 0 ? "frame-left" : "frame-right", {x, 1.4f, 0.0f}, {0.04f, 1.42f, 3.62f},
           {0.12f, 0.08f, 0.05f});
  addBox(s, "red-box", {0.0f, 0.4f, 0.0f}, vec3(0.4f), {0.85f, 0.18f, 0.12f}, 20.0f);
  addObject(s, "blue-sphere", procedural::sphere(0.35f, 48, 24),
            Material::diffuse("blue", {0.15f, 0.3f, 0.85f}), placeAt({0.9f, 0.35f, -0.8f}));
  addObject(s, "column", procedural::cylinder(0.2f, 1.4f),
            Material::diffuse("yellow", {0.9f, 0.8f, 0.15f}), placeAt({-1.0f, 0.0f, 0.7f}));
  addMainCamera(s, {2.3f, 1.8f, 3.0f}, {-3.0f, 1.1f, -1.2f}, 55.0f);
  // Six seconds along the right mirror, between the mirrors (in front of both), looking across at
  // the left one.
  addWalkCamera(s,
                {{0.0f, {2.2f, 1.7f, 3.0f}, {-3.0f, 1.2f, 0.8f}},
                 {2.0f, {2.0f, 1.65f, 1.2f}, {-3.0f, 1.2f, -0.6f}},
                 {4.0f, {2.1f, 1.7f, -0.6f}, {-3.0f, 1.2f, -1.8f}},
                 {6.0f, {2.3f, 1.75f, -2.4f}, {-3.0f, 1.2f, -2.6f}}},
                55.0f);
  return s;
}

// The goblet's profile (radius, y): foot and stem, the bowl's outside up to the rim, over the rim
// and down the bowl's inside to the axis, so that the inside is a concave mirror. About 1.2 tall.
std::vector<vec2> gobletProfile() {
  std::vector<vec2> p = {{0.0f, 0.0f},    {0.34f, 0.0f},  {0.36f, 0.01f},  {0.345f, 0.025f},
                         {0.22f, 0.045f}, {0.1f, 0.075f}, {0.045f, 0.12f}, {0.032f, 0.22f},
                         {0.032f, 0.48f}, {0.045f, 0.58f}};
  // The bowl: an ellipsoidal cap of rim radius `radius` and depth `depth` above y = `bottom`,
  // its wall `wall` thick.
  const float radius = 0.48f, depth = 0.5f, bottom = 0.68f, wall = 0.015f;
  const int outer = 9, inner = 10;
  const float t0 = std::asin(0.075f / radius);  // where the stem meets the bowl
  for (int i = 0; i < outer; ++i) {
    float t = t0 + (0.5f * kPi - t0) * float(i) / float(outer - 1);
    p.push_back({radius * std::sin(t), bottom + depth * (1.0f - std::cos(t))});
  }
  p.push_back({radius - 0.5f * wall, bottom + depth + 0.008f});  // the rounded rim
  for (int i = inner - 1; i >= 0; --i) {
    float t = 0.5f * kPi * float(i) / float(inner - 1);
    p.push_back(
        {(radius - wall) * std::sin(t), bottom + wall + (depth - wall) * (1.0f - std::cos(t))});
  }
  return p;
}

// A cylinder along +Y turned to point along `direction`.
quat alongDirection(vec3 direction) {
  vec3 d = glm::normalize(direction), y(0, 1, 0);
  vec3 axis = glm::cross(y, d);
  float len = glm::length(axis);
  if (len < 1e-6f) return quat(1, 0, 0, 0);
  return glm::angleAxis(std::acos(glm::clamp(glm::dot(y, d), -1.0f, 1.0f)), axis / len);
}

// The hybrid paper's glass (its Figure 3): a goblet-shaped mirror whose concave bowl shows the
// objects around it inverted and doubled, and a straw that intersects the reflector (Figure 2).
Scene glass(const SceneOptions&) {
  Scene s;
  addCheckerFloor(s, 16.0f);
  int goblet = addMesh(s, procedural::lathe(gobletProfile(), 80));
  s.meshes[size_t(goblet)].name = "goblet";
  int mirror = addMaterial(s, Material::mirror("mirror"));
  addInstance(s, "goblet", goblet, mirror, {});
  // The straw: from the bowl's inside through the rim on the far side.
  vec3 straw_base(-0.1f, 0.72f, 0.06f), rim_point(0.335f, 1.18f, -0.335f);
  int straw = addMesh(s, procedural::cylinder(0.022f, 1.2f, 24));
  int red = addMaterial(s, Material::diffuse("straw", {0.9f, 0.15f, 0.2f}));
  addInstance(s, "straw", straw, red,
              placeAt(straw_base, vec3(1.0f), alongDirection(rim_point - straw_base)));
  addBox(s, "orange-box", {0.75f, 0.7f, -0.1f}, {0.16f, 0.7f, 0.16f}, {0.95f, 0.5f, 0.1f}, 25.0f);
  addObject(s, "purple-column", procedural::cylinder(0.12f, 1.6f, 48),
            Material::diffuse("purple", {0.55f, 0.25f, 0.7f}), placeAt({-0.85f, 0.0f, 0.2f}));
  addBox(s, "blue-box", {0.5f, 0.35f, 0.8f}, {0.13f, 0.35f, 0.13f}, {0.15f, 0.3f, 0.85f}, 10.0f);
  // A hoop standing in front of the goblet, the camera looking through it: the bowl's inside
  // shows it upside down.
  addObject(s, "yellow-hoop", procedural::torus(1.0f, 0.08f, 96, 24),
            Material::diffuse("yellow", {0.9f, 0.8f, 0.15f}), placeAt({0.0f, 1.08f, 0.75f}));
  addMainCamera(s, {0.15f, 2.0f, 1.9f}, {0.0f, 0.85f, 0.0f}, 38.0f);
  return s;
}

// A coarse concave mirror (a spherical cap of radius 1 in ten segments and five rings, smooth
// normals) with a ball near the eye's caustic: its reflector triangles are large C3RCs that
// converge and then diverge, where one C3RC projects a point twice (the hybrid paper's Figure 3).
Scene concaveDish(const SceneOptions&) {
  Scene s;
  addObject(s, "dish", procedural::lathe(capProfile(40.0f, 5), 10), Material::mirror("mirror"), {});
  addObject(s, "ball", procedural::sphere(0.08f, 64, 32),
            Material::diffuse("red", {0.9f, 0.2f, 0.2f}), placeAt({0.03f, 0.66f, -0.3f}));
  addMainCamera(s, {0.0f, 2.2f, 0.9f}, {0.0f, 0.1f, 0.0f}, 35.0f);
  return s;
}

// A rippling mirror pool: a 4 x 3 mirror grid just above a checkerboard, waves running out from
// a point near one end (a deforming reflector), with coloured objects around its rim.
Scene ripplePool(const SceneOptions&) {
  Scene s;
  addCheckerFloor(s, 16.0f);
  const int pool_instance =
      addObject(s, "pool", procedural::quad(4.0f, 3.0f, 1.0f, 96, 72),
                Material::mirror("water", vec3(0.04f, 0.06f, 0.08f)), placeAt({0.0f, 0.06f, 0.0f}));
  Deformation& ripple = s.instances[size_t(pool_instance)].deformation;
  ripple.kind = Deformation::Kind::kRipple;
  ripple.amplitude = 0.025f;
  ripple.wavelength = 0.5f;
  ripple.speed = 0.2f;
  ripple.decay = 2.5f;
  ripple.center = vec3(-0.9f, 0.0f, -0.4f);
  addBox(s, "red-box", {-1.4f, 0.35f, -2.0f}, vec3(0.35f), {0.85f, 0.18f, 0.12f}, 20.0f);
  addBox(s, "blue-box", {1.3f, 0.5f, -2.1f}, {0.3f, 0.5f, 0.3f}, {0.15f, 0.3f, 0.85f}, -15.0f);
  addObject(s, "column", procedural::cylinder(0.18f, 1.5f),
            Material::diffuse("yellow", {0.9f, 0.8f, 0.15f}), placeAt({2.4f, 0.0f, -0.6f}));
  addObject(s, "teapot", procedural::teapotLike(),
            Material::diffuse("purple", {0.55f, 0.25f, 0.7f}),
            placeAt({-2.5f, 0.0f, 0.3f}, vec3(1.0f), rotationY(60)));
  addObject(s, "green-ball", procedural::sphere(0.3f, 48, 24),
            Material::diffuse("green", {0.2f, 0.7f, 0.25f}), placeAt({0.3f, 0.3f, -1.9f}));
  addMainCamera(s, {0.4f, 2.2f, 4.2f}, {0.0f, 0.2f, -0.6f}, 45.0f);
  return s;
}

}  // namespace

int addMesh(Scene& scene, Mesh mesh) {
  scene.meshes.push_back(std::move(mesh));
  return int(scene.meshes.size()) - 1;
}

int addMaterial(Scene& scene, Material material) {
  scene.materials.push_back(std::move(material));
  return int(scene.materials.size()) - 1;
}

int addInstance(Scene& scene, std::string name, int mesh, int material,
                const Transform& transform) {
  Instance inst;
  inst.name = std::move(name);
  inst.mesh = mesh;
  inst.material = material;
  inst.transform = transform;
  scene.instances.push_back(std::move(inst));
  return int(scene.instances.size()) - 1;
}

int addObject(Scene& scene, std::string name, Mesh mesh, Material material,
              const Transform& transform) {
  const int mesh_index = addMesh(scene, std::move(mesh));
  const int material_index = addMaterial(scene, std::move(material));
  return addInstance(scene, std::move(name), mesh_index, material_index, transform);
}

void addBox(Scene& s, const char* name, vec3 center, vec3 half, vec3 color, float yaw) {
  addObject(s, name, procedural::box(half), Material::diffuse(name, color),
            placeAt(center, vec3(1.0f), rotationY(yaw)));
}

Transform placeAt(vec3 translation, vec3 scale, quat rotation) {
  Transform t;
  t.translation = translation;
  t.scale = scale;
  t.rotation = rotation;
  return t;
}

namespace {

struct BuiltinMaker {
  const char* name;
  const char* description;  // what `mirage scenes` lists, without building the scene
  Scene (*make)(const SceneOptions&);
};

// The built-in scenes, in the order `mirage scenes` lists them.
constexpr BuiltinMaker kBuiltins[] = {
    {"sphere-over-checker",
     "one mirror sphere over a checkerboard floor with coloured boxes around it",
     sphereOverChecker},
    {"spheres9", "a 3x3 grid of mirror spheres among diffuse objects (--reflectors N keeps N)",
     spheres9},
    {"mirror-room",
     "a checkerboard room with one planar wall mirror, a teapot-like object on an "
     "inverted pyramid and a box",
     mirrorRoom},
    {"two-mirrors",
     "two facing planar mirrors with objects between them (reflections of every order)",
     twoMirrors},
    {"teapot-sphere",
     "a teapot and a standing torus reflected in a mirror sphere on a checkerboard (depth maps)",
     teapotSphere},
    {"mirror-torus",
     "a standing mirror torus beside a teapot on a checkerboard, seen into its hole: the inner "
     "surface reflects itself (self-reflections)",
     mirrorTorus},
    {"glass",
     "a mirror goblet on a checkerboard with coloured objects around it and a straw through its "
     "rim: the concave bowl shows them inverted and doubled (the hybrid paper's glass)",
     glass},
    {"concave-dish",
     "a coarse concave mirror dish with a ball near its focus: large convergent-then-divergent "
     "C3RCs, the case for a second projection inside one C3RC (hybrid paper, Figure 3)",
     concaveDish},
    {"ripple-pool",
     "a rippling mirror pool on a checkerboard with objects around it: a deforming reflector "
     "(waves from a point, 2.5 s period)",
     ripplePool},
    {"gallery",
     "a room of mixed reflectors: two planar wall mirrors, a mirror sphere, a mirror teapot and a "
     "concave mirror among eleven diffuse objects of different sizes (per-reflector techniques)",
     galleryScene},
    {"plaza",
     "the scale case: 240 diffuse objects (over a million triangles) on a square among 20 "
     "mirrors, 14 curved (12 spheres, 2 teapots) and 6 planar panels (--objects N lays out N, "
     "--reflectors N keeps N of up to 32)",
     plazaScene},
};

const BuiltinMaker* findBuiltin(const std::string& name) {
  for (const BuiltinMaker& b : kBuiltins)
    if (name == b.name) return &b;
  return nullptr;
}

}  // namespace

const std::vector<BuiltinSceneInfo>& builtinScenes() {
  static const std::vector<BuiltinSceneInfo> scenes = [] {
    std::vector<BuiltinSceneInfo> v;
    for (const BuiltinMaker& b : kBuiltins) v.push_back({b.name, b.description});
    return v;
  }();
  return scenes;
}

bool isBuiltinScene(const std::string& name) {
  return findBuiltin(name) != nullptr;
}

Scene makeBuiltinScene(const std::string& name, const SceneOptions& options) {
  const BuiltinMaker* maker = findBuiltin(name);
  if (!maker) throwInput("unknown built-in scene '{}'", name);
  Scene s = maker->make(options);
  if (options.reflectors >= 0 && name != "spheres9" && name != "plaza")
    throwInput("--reflectors applies to spheres9 and plaza only, not to '{}'", name);
  if (options.objects >= 0 && name != "plaza")
    throwInput("--objects applies to plaza only, not to '{}'", name);
  s.name = name;
  s.description = maker->description;
  s.source = "builtin:" + name;
  s.validate();
  return s;
}

}  // namespace mirage
