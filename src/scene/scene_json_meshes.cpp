// Meshes (procedural or files, with `fit` and `subdivide`), instances (mesh + material, or a whole
// model file) and their keyframed animation.
#include <algorithm>

#include "scene/loader_support.h"
#include "scene/model_loader.h"
#include "scene/procedural.h"
#include "scene/scene_json_internal.h"

namespace mirage::scene_json {

namespace {

// Sizes and scales: bounded so that no product of them (uvs, areas, positions) overflows a float.
const Range kSize = Range{0.0, 1e6, true, false};

constexpr const char* kGenerators =
    "sphere, box, quad, cylinder, lathe, torus, pyramid, teapot-like";

Mesh parseProcedural(const Field& f) {
  Field kind = f.required("procedural");
  std::string type = kind.string();
  if (type == "sphere") {
    f.allowKeys({"name", "procedural", "radius", "segments", "rings"}, "a procedural sphere");
    return procedural::sphere(f.numberOr("radius", 1.0f, kSize),
                              f.integerOr("segments", 96, 3, 2048),
                              f.integerOr("rings", 48, 2, 1024));
  }
  if (type == "box") {
    f.allowKeys({"name", "procedural", "size", "inward"}, "a procedural box");
    vec3 size = f.vector3Or("size", vec3(1.0f), kSize);
    return procedural::box(0.5f * size, f.booleanOr("inward", false));
  }
  if (type == "quad") {
    f.allowKeys({"name", "procedural", "size", "uv_per_unit", "cells"}, "a procedural quad");
    vec2 size(1.0f);
    if (auto s = f.optional("size")) size = s->vector2(kSize);
    ivec2 cells(1);
    if (auto c = f.optional("cells")) {
      const vec2 v = c->vector2(Range::closed(1.0, 1024.0));
      cells = ivec2(v);
      if (vec2(cells) != v) c->fail("must hold two whole numbers in 1..1024");
    }
    return procedural::quad(size.x, size.y, f.numberOr("uv_per_unit", 1.0f, kSize), cells.x,
                            cells.y);
  }
  if (type == "cylinder") {
    f.allowKeys({"name", "procedural", "radius", "height", "segments"}, "a procedural cylinder");
    return procedural::cylinder(f.numberOr("radius", 0.5f, kSize),
                                f.numberOr("height", 1.0f, kSize),
                                f.integerOr("segments", 48, 3, 2048));
  }
  if (type == "lathe") {
    f.allowKeys({"name", "procedural", "profile", "segments"}, "a procedural lathe");
    Field profile = f.required("profile");
    std::vector<Field> points = profile.items();
    if (points.size() < 2 || points.size() > 4096)
      profile.fail("has {} points; a profile needs 2..4096 [radius, y] points", points.size());
    std::vector<vec2> p;
    bool any_radius = false;
    for (const Field& point : points) {
      vec2 v = point.vector2(Range::closed(-1e6, 1e6));
      if (v.x < 0.0f) point.fail("has radius {}; radii must be >= 0", v.x);
      any_radius = any_radius || v.x > 0.0f;
      p.push_back(v);
    }
    if (!any_radius) profile.fail("has only radius-0 points; the surface would be empty");
    return procedural::lathe(p, f.integerOr("segments", 64, 3, 2048));
  }
  if (type == "torus") {
    f.allowKeys({"name", "procedural", "major_radius", "minor_radius", "segments", "sides"},
                "a procedural torus");
    return procedural::torus(
        f.numberOr("major_radius", 1.0f, kSize), f.numberOr("minor_radius", 0.25f, kSize),
        f.integerOr("segments", 48, 3, 2048), f.integerOr("sides", 24, 3, 1024));
  }
  if (type == "pyramid") {
    f.allowKeys({"name", "procedural", "half_width", "height", "inverted"}, "a procedural pyramid");
    return procedural::pyramid(f.numberOr("half_width", 0.5f, kSize),
                               f.numberOr("height", 1.0f, kSize), f.booleanOr("inverted", false));
  }
  if (type == "teapot-like") {
    f.allowKeys({"name", "procedural", "segments"}, "a procedural teapot-like");
    // The handle is a torus of segments / 2 rings, which needs at least 3.
    return procedural::teapotLike(f.integerOr("segments", 48, 6, 2048));
  }
  kind.fail("= {} is not a procedural mesh (allowed: {})", shortQuote(type), kGenerators);
}

Fit parseFit(const Field& f) {
  f.allowKeys({"size", "ground"}, "fit");
  Fit fit;
  fit.size = f.numberOr("size", fit.size, kSize);
  fit.ground = f.booleanOr("ground", fit.ground);
  return fit;
}

// The mesh entry named by a string field.
MeshEntry& meshEntry(Context& ctx, const Field& field) {
  return ctx.meshes[size_t(lookupName(ctx.mesh_index, field, "mesh"))];
}

// The instance's own name or `<mesh>-<index + 1>`; names must differ.
std::string instanceName(const Field& f, size_t index, const std::string& mesh,
                         std::map<std::string, int>& names) {
  std::string name = f.stringOr("name", fmt::format("{}-{}", mesh, index + 1));
  if (!names.emplace(name, int(index)).second) {
    if (auto given = f.optional("name"))
      given->fail("= {} is already the name of another instance", shortQuote(name));
    f.fail("gets the default name {}, which another instance has; give it a name",
           shortQuote(name));
  }
  return name;
}

// Applies `fit` (if any) to meshes placed by `placement`; throws for a mesh without extent.
template <typename Meshes>
void applyFit(const MeshEntry& entry, Meshes& meshes) {
  if (!entry.fit) return;
  Bounds3 b;
  for (const Mesh& m : meshes) b.extend(m.bounds());
  vec3 e = b.extent();
  if (b.empty() || !(std::max({e.x, e.y, e.z}) > 0.0f))
    throwInput("{}.fit: the mesh has no extent to fit", entry.where);
  mat4 m = fitMatrix(b, *entry.fit);
  for (Mesh& mesh : meshes) mesh.transform(m);
}

// Applies `subdivide` (if any) to the entry's meshes, after fitting. The result stays within the
// readers' limits (LoadLimits), so that 4 rounds of a large model fail with a message instead of
// running out of memory.
template <typename Meshes>
void applySubdivide(const MeshEntry& entry, Meshes& meshes) {
  if (entry.subdivide <= 0) return;
  const LoadLimits limits;
  uint64_t vertices = 0, triangles = 0;
  for (const Mesh& m : meshes) {
    vertices += m.vertexCount();
    triangles += m.triangleCount();
  }
  for (int round = 0; round < entry.subdivide; ++round) {
    vertices += 3 * triangles;  // an upper bound: V + E <= V + 3T
    triangles *= 4;
  }
  if (vertices > limits.max_vertices || triangles > limits.max_triangles)
    throwInput(
        "{}.subdivide = {}: the mesh would have {} triangles (up to {} vertices); at most {} "
        "triangles and {} vertices are allowed",
        entry.where, entry.subdivide, triangles, vertices, limits.max_triangles,
        limits.max_vertices);
  checkAllocation(entry.where,
                  fmt::format("subdivide = {} ({} triangles)", entry.subdivide, triangles),
                  loader::meshBytes(vertices, triangles), limits.max_bytes);
  for (Mesh& mesh : meshes)
    for (int round = 0; round < entry.subdivide; ++round) mesh = subdivideMidpoint(mesh);
}

// The entry as one mesh in the scene (loaded and fitted on first use).
int sceneMesh(Context& ctx, MeshEntry& entry) {
  if (entry.scene_mesh >= 0) return entry.scene_mesh;
  std::vector<Mesh> one;
  if (entry.procedural) {
    one.push_back(*entry.procedural);
  } else {
    try {
      one.push_back(loadMesh(entry.file));
    } catch (const Error& e) {
      throwInput("{}: {}", entry.file_where, e.what());
    }
    one[0].source = entry.file;
  }
  applyFit(entry, one);
  applySubdivide(entry, one);
  one[0].name = entry.name;
  ctx.scene.meshes.push_back(std::move(one[0]));
  entry.scene_mesh = int(ctx.scene.meshes.size()) - 1;
  return entry.scene_mesh;
}

// The entry as a model: its meshes placed by their node transforms, its materials and textures
// appended to the scene (loaded on first use).
const std::vector<std::pair<int, int>>& modelParts(Context& ctx, MeshEntry& entry,
                                                   const Field& at) {
  if (entry.model_loaded) return entry.model_parts;
  if (entry.procedural)
    at.fail("names the procedural mesh {}; model needs a mesh file entry", shortQuote(entry.name));
  LoadedModel model;
  try {
    model = loadModel(entry.file);
  } catch (const Error& e) {
    throwInput("{}: {}", entry.file_where, e.what());
  }
  for (size_t i = 0; i < model.meshes.size(); ++i)
    if (i < model.mesh_transform.size()) model.meshes[i].transform(model.mesh_transform[i]);
  applyFit(entry, model.meshes);
  applySubdivide(entry, model.meshes);
  Scene& s = ctx.scene;
  int texture_base = int(s.textures.size());
  for (TextureImage& t : model.textures) s.textures.push_back(std::move(t));
  int material_base = int(s.materials.size());
  for (Material m : model.materials) {
    m.name = entry.name + "/" + m.name;
    if (m.albedo_texture >= 0) m.albedo_texture += texture_base;
    if (m.normal_map >= 0) m.normal_map += texture_base;
    s.materials.push_back(std::move(m));
  }
  for (size_t i = 0; i < model.meshes.size(); ++i) {
    Mesh& mesh = model.meshes[i];
    if (mesh.name.empty()) mesh.name = fmt::format("{}/{}", entry.name, i);
    mesh.source = entry.file;
    int material = i < model.mesh_material.size() ? model.mesh_material[i] : -1;
    s.meshes.push_back(std::move(mesh));
    entry.model_parts.push_back(
        {int(s.meshes.size()) - 1, material < 0 ? -1 : material_base + material});
  }
  entry.model_loaded = true;
  return entry.model_parts;
}

Transform parseTransform(const Field& f, Transform t) {
  if (auto v = f.optional("translate")) t.translation = v->vector3(Range::closed(-1e6, 1e6));
  if (auto v = f.optional("rotate")) t.rotation = eulerDegrees(v->vector3());
  if (auto v = f.optional("scale")) {
    if (v->json().is_number())
      t.scale = vec3(v->number(kSize));
    else if (v->json().is_array())
      t.scale = v->vector3(kSize);
    else
      v->fail("= {}: expected a number or an array of 3 numbers (each in (0, 1000000])",
              v->describe());
  }
  return t;
}

Animation parseAnimation(const Field& f, const Transform& base) {
  f.allowKeys({"loop", "keys"}, "an animation");
  Animation a;
  a.loop = f.booleanOr("loop", false);
  Field keys = f.required("keys");
  std::vector<Field> items = keys.items();
  if (items.empty()) keys.fail("is empty; an animation needs at least one key");
  for (const Field& k : items) {
    k.allowKeys({"time", "translate", "rotate", "scale"}, "an animation key");
    Keyframe key;
    key.time = keyTime(k, a.keys.empty() ? std::nullopt : std::optional<float>(a.keys.back().time));
    // Fields a key leaves out keep the instance's own translate/rotate/scale.
    key.transform = parseTransform(k, base);
    a.keys.push_back(key);
  }
  return a;
}

// "deform": {"type": "ripple", "amplitude", "wavelength", "speed", "decay", "center"}.
Deformation parseDeformation(const Field& f) {
  f.allowKeys({"type", "amplitude", "wavelength", "speed", "decay", "center"}, "a deformation");
  Field type = f.required("type");
  if (type.string() != "ripple")
    type.fail("= {} is not a deformation (allowed: ripple)", shortQuote(type.string()));
  Deformation d;
  d.kind = Deformation::Kind::kRipple;
  d.amplitude = f.numberOr("amplitude", 0.02f, Range::closed(-1e3, 1e3));
  d.wavelength = f.numberOr("wavelength", d.wavelength, Range{0.0, 1e6, true, false});
  d.speed = f.numberOr("speed", d.speed, Range::closed(-1e6, 1e6));
  d.decay = f.numberOr("decay", d.decay, Range::closed(0.0, 1e6));
  if (auto c = f.optional("center")) d.center = c->vector3(Range::closed(-1e6, 1e6));
  return d;
}

bool needsUvs(const Material& m) {
  return m.albedo_texture >= 0 || m.checker_scale > 0.0f || m.normal_map >= 0;
}

// The instance's "layer" (scene/layers.h), if given: diffuse instances only.
std::optional<Layer> parseLayer(const Field& instance, const Material& material) {
  const std::optional<Field> f = instance.optional("layer");
  if (!f) return std::nullopt;
  const std::string text = f->string();
  const std::optional<Layer> layer = findChoice<Layer>(kLayers, text);
  if (!layer)
    f->fail("= {}: unknown layer (allowed: {})", shortQuote(text), choiceNames<Layer>(kLayers));
  if (material.isReflector())
    f->fail("applies to diffuse instances only; material {} is a reflector (reflectors are in no "
            "layer)",
            shortQuote(material.name));
  return layer;
}

void addInstance(Context& ctx, const Field& at, std::string name, int mesh, int material,
                 const Transform& t, const Animation& a, const Deformation& deformation) {
  Scene& s = ctx.scene;
  if (deformation.active()) {
    if (!s.materials[size_t(material)].isReflector())
      at.required("deform").fail("applies to reflectors only; material {} is diffuse",
                                 shortQuote(s.materials[size_t(material)].name));
    // A deforming instance changes its mesh: it gets a copy of its own.
    Mesh copy = s.meshes[size_t(mesh)];
    copy.name += "@" + name;
    s.meshes.push_back(std::move(copy));
    mesh = int(s.meshes.size()) - 1;
  }
  Mesh& m = s.meshes[size_t(mesh)];
  const Material& mat = s.materials[size_t(material)];
  if (needsUvs(mat) && m.uvs.size() != m.positions.size())
    at.fail(
        "gives mesh {} material {}, which needs texture coordinates (a texture, checker or "
        "normal map), but the mesh has none",
        shortQuote(m.name), shortQuote(mat.name));
  if (mat.normal_map >= 0 && m.tangents.size() != m.positions.size()) m.computeTangents();
  Instance inst;
  inst.name = std::move(name);
  inst.mesh = mesh;
  inst.material = material;
  inst.transform = t;
  inst.animation = a;
  inst.deformation = deformation;
  inst.layer = parseLayer(at, mat);
  s.instances.push_back(std::move(inst));
}

}  // namespace

quat eulerDegrees(const vec3& d) {
  return glm::angleAxis(radians(d.z), vec3(0, 0, 1)) * glm::angleAxis(radians(d.y), vec3(0, 1, 0)) *
         glm::angleAxis(radians(d.x), vec3(1, 0, 0));
}

mat4 fitMatrix(const Bounds3& b, const Fit& fit) {
  vec3 e = b.extent();
  float scale = fit.size / std::max({e.x, e.y, e.z});
  vec3 c = b.center();
  vec3 anchor(c.x, fit.ground ? b.lo.y : c.y, c.z);
  return glm::scale(mat4(1.0f), vec3(scale)) * glm::translate(mat4(1.0f), -anchor);
}

void parseMeshes(Context& ctx, const Field& root) {
  auto list = root.optional("meshes");
  if (!list) return;
  for (const Field& f : list->items()) {
    f.requireObject("a mesh");
    MeshEntry e;
    Field name = f.required("name");
    e.name = name.string();
    if (!ctx.mesh_index.emplace(e.name, int(ctx.meshes.size())).second)
      name.fail("= {} is already the name of another mesh", shortQuote(e.name));
    e.where = f.where();
    bool is_file = f.has("file"), is_procedural = f.has("procedural");
    if (is_file == is_procedural)
      f.fail("needs exactly one of file (a mesh file) or procedural (one of {})", kGenerators);
    if (is_file) {
      f.allowKeys({"name", "file", "fit", "subdivide"}, "a mesh from a file");
      Field file = f.required("file");
      e.file_where = file.where();
      e.file = resolvePath(ctx, file);
      if (!isModelFile(e.file))
        file.fail(
            "= {}: not a mesh file (.ply, .ply.gz, .obj, .gltf, .glb, or a format assimp reads)",
            shortQuote(file.string(), 200));
      if (auto fit = f.optional("fit")) e.fit = parseFit(*fit);
      e.subdivide = f.integerOr("subdivide", 0, 0, 4);
    } else {
      e.procedural = parseProcedural(f);
      e.procedural->name = e.name;
      try {
        e.procedural->validate();
      } catch (const InputError& err) {
        f.fail("generates no valid mesh: {}", err.what());
      }
    }
    ctx.meshes.push_back(std::move(e));
  }
}

void parseInstances(Context& ctx, const Field& root) {
  Field list = root.required("instances");
  std::vector<Field> items = list.items();
  if (items.empty()) list.fail("is empty; a scene needs at least one instance");
  std::map<std::string, int> names;
  for (size_t i = 0; i < items.size(); ++i) {
    const Field& f = items[i];
    f.allowKeys({"name", "mesh", "material", "model", "material_override", "translate", "rotate",
                 "scale", "animation", "deform", "layer"},
                "an instance");
    Transform t = parseTransform(f, {});
    Animation a;
    if (auto anim = f.optional("animation")) a = parseAnimation(*anim, t);
    Deformation deformation;
    if (auto d = f.optional("deform")) deformation = parseDeformation(*d);
    if (auto model = f.optional("model")) {
      for (const char* key : {"mesh", "material"})
        if (auto other = f.optional(key))
          other->fail(
              "cannot be combined with model (a model brings its meshes and materials; "
              "material_override replaces them)");
      MeshEntry& entry = meshEntry(ctx, *model);
      std::string name = instanceName(f, i, entry.name, names);
      int override_material = -1;
      if (auto o = f.optional("material_override"))
        override_material = lookupName(ctx.material_index, *o, "material");
      std::vector<std::pair<int, int>> parts = modelParts(ctx, entry, *model);
      for (auto [mesh, material] : parts) {
        if (override_material >= 0) material = override_material;
        if (material < 0) {
          // Formats without materials (PLY, STL): a neutral grey, so the model still shows.
          if (ctx.default_model_material < 0) {
            ctx.scene.materials.push_back(Material::diffuse("model-default", vec3(0.7f)));
            ctx.default_model_material = int(ctx.scene.materials.size()) - 1;
          }
          material = ctx.default_model_material;
        }
        std::string part =
            parts.size() == 1 ? name : name + "/" + ctx.scene.meshes[size_t(mesh)].name;
        addInstance(ctx, f, part, mesh, material, t, a, deformation);
      }
      continue;
    }
    if (auto o = f.optional("material_override"))
      o->fail("applies to model instances only (use material with mesh)");
    Field mesh_field = f.required("mesh");
    MeshEntry& entry = meshEntry(ctx, mesh_field);
    int material = lookupName(ctx.material_index, f.required("material"), "material");
    std::string name = instanceName(f, i, entry.name, names);
    addInstance(ctx, f, name, sceneMesh(ctx, entry), material, t, a, deformation);
  }
}

}  // namespace mirage::scene_json
