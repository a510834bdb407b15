// The top level of a scene file and the sections that need no geometry: environment, light,
// textures, materials, cameras. Meshes and instances are in scene_json_meshes.cpp.
#include "scene/scene_json.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <spdlog/spdlog.h>

#include "core/image.h"
#include "scene/scene_json_internal.h"
#include "scene/scene_loader.h"

namespace mirage {

namespace fs = std::filesystem;
using scene_json::Context;
using scene_json::Field;
using scene_json::Json;
using scene_json::Range;
using scene_json::shortQuote;

namespace scene_json {

namespace {

const Range kUnit = Range::closed(0.0, 1.0);
const Range kNonNegative = Range::atLeast(0.0);

bool isAssetReference(const std::string& s) {
  return s.rfind(kAssetPrefix, 0) == 0;
}

bool isFile(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec);
}

void parseEnvironment(Context& ctx, const Field& f) {
  f.allowKeys({"image", "intensity", "rotation", "clamp", "cube_size"}, "environment");
  EnvironmentDesc& env = ctx.scene.environment;
  if (auto image = f.optional("image")) {
    env.image = resolvePath(ctx, *image);
    // The image is decoded when the environment is built for rendering; a wrong kind of file is
    // caught here, where the field can still be named.
    std::string ext = fs::path(env.image).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    bool known = false;
    for (const char* e : {".exr", ".hdr", ".png", ".jpg", ".jpeg", ".tga", ".bmp"})
      known |= ext == e;
    if (!known)
      image->fail("= {}: not an image file (allowed: .exr, .hdr, .png, .jpg, .jpeg, .tga, .bmp)",
                  shortQuote(image->string(), 200));
  }
  env.intensity = f.numberOr("intensity", env.intensity, kNonNegative);
  env.rotation_degrees = f.numberOr("rotation", env.rotation_degrees);
  env.clamp = f.numberOr("clamp", env.clamp, kNonNegative);
  if (auto size = f.optional("cube_size")) {
    env.cube_size = size->integer(0, 4096);
    if (env.cube_size != 0 && env.cube_size < 8)
      size->fail("= {} is outside the allowed values (0 = automatic, or 8..4096)", env.cube_size);
  }
}

vec3 lightDirection(const Field& dir) {
  const vec3 d = dir.vector3(Range::closed(-1e6, 1e6));
  if (!(glm::length(d) > 1e-6f)) dir.fail("= [0, 0, 0]: the direction must not be zero");
  return glm::normalize(d);
}

// "keys": [{"time", "direction", "color"}, ...]: a moving light. A key's direction and colour
// default to the light's own.
void parseLightKeys(Light& light, const Field& f) {
  std::vector<Field> items = f.items();
  if (items.empty()) f.fail("is empty; a moving light needs at least one key");
  for (const Field& k : items) {
    k.allowKeys({"time", "direction", "color"}, "a light key");
    LightKey key;
    key.time = keyTime(
        k, light.keys.empty() ? std::nullopt : std::optional<float>(light.keys.back().time));
    auto dir = k.optional("direction");
    key.direction = dir ? lightDirection(*dir) : light.direction;
    if (!light.keys.empty() && glm::dot(key.direction, light.keys.back().direction) < -0.999f)
      (dir ? *dir : k)
          .fail(
              "is opposite the previous key's direction; the light's turn between "
              "them is undefined (add a key in between)");
    key.color = k.vector3Or("color", light.color, kNonNegative);
    light.keys.push_back(key);
  }
}

void parseLight(Context& ctx, const Field& f) {
  f.allowKeys({"direction", "color", "ambient", "keys", "loop"}, "light");
  Light& light = ctx.scene.light;
  if (auto dir = f.optional("direction")) light.direction = lightDirection(*dir);
  light.color = f.vector3Or("color", light.color, kNonNegative);
  light.ambient = f.vector3Or("ambient", light.ambient, kNonNegative);
  light.loop = f.booleanOr("loop", false);
  if (auto keys = f.optional("keys")) parseLightKeys(light, *keys);
}

struct TextureEntry {
  std::string where;
  std::string path;
  std::optional<bool> srgb;
  bool normal_map = false;
};

std::vector<TextureEntry> parseTextures(Context& ctx, const Field& list) {
  std::vector<TextureEntry> out;
  for (const Field& f : list.items()) {
    f.allowKeys({"name", "file", "srgb"}, "a texture");
    Field name = f.required("name");
    std::string n = name.string();
    if (!ctx.texture_index.emplace(n, int(out.size())).second)
      name.fail("= {} is already the name of another texture", shortQuote(n));
    TextureEntry t;
    t.where = f.required("file").where();
    t.path = resolvePath(ctx, f.required("file"));
    if (auto srgb = f.optional("srgb")) t.srgb = srgb->boolean();
    out.push_back(std::move(t));
    ctx.scene.textures.push_back({n, {}, true});
  }
  return out;
}

// Textures are decoded once the materials say which are normal maps: those default to linear
// data, every other texture to sRGB colour.
void loadTextures(Context& ctx, std::vector<TextureEntry>& entries) {
  for (size_t i = 0; i < entries.size(); ++i) {
    TextureImage& t = ctx.scene.textures[i];
    t.srgb = entries[i].srgb.value_or(!entries[i].normal_map);
    try {
      t.image = readImage(entries[i].path, t.srgb ? Encoding::kSrgb : Encoding::kLinear);
    } catch (const Error& e) {
      throwInput("{}: {}", entries[i].where, e.what());
    }
  }
}

Material parseMaterial(Context& ctx, const Field& f, std::vector<TextureEntry>& textures) {
  f.requireObject("a material");
  Material m;
  m.name = f.required("name").string();
  Field type = f.required("type");
  std::string kind = type.string();
  if (kind == "diffuse") {
    f.allowKeys({"name", "type", "albedo", "checker", "texture"}, "a diffuse material");
    m.albedo = f.vector3Or("albedo", m.albedo, kUnit);
    if (auto checker = f.optional("checker")) {
      checker->allowKeys({"color", "scale"}, "a checker");
      m.checker_color = checker->vector3Or("color", m.checker_color, kUnit);
      m.checker_scale = checker->numberOr("scale", 1.0f, Range::above(0.0));
    }
    if (auto tex = f.optional("texture")) {
      // The shading model draws either the checker or the texture (shading/shading.h).
      if (m.checker_scale > 0.0f) tex->fail("cannot be combined with checker: use one of them");
      m.albedo_texture = lookupName(ctx.texture_index, *tex, "texture");
    }
  } else if (kind == "reflector") {
    f.allowKeys({"name", "type", "base", "tint", "reflectivity", "fresnel_f0", "attenuation_range",
                 "normal_map", "planar"},
                "a reflector material");
    m.kind = Material::Kind::kReflector;
    m.planar = f.booleanOr("planar", false);
    m.albedo = f.vector3Or("base", vec3(0.05f), kUnit);
    m.tint = f.vector3Or("tint", m.tint, kUnit);
    m.reflectivity = f.numberOr("reflectivity", m.reflectivity, kUnit);
    m.fresnel_f0 = f.numberOr("fresnel_f0", m.fresnel_f0, kUnit);
    m.attenuation_range = f.numberOr("attenuation_range", m.attenuation_range, kNonNegative);
    if (auto tex = f.optional("normal_map")) {
      m.normal_map = lookupName(ctx.texture_index, *tex, "texture");
      textures[size_t(m.normal_map)].normal_map = true;
    }
  } else {
    type.fail("= {} is not a material type (allowed: diffuse, reflector)", shortQuote(kind));
  }
  return m;
}

// Every file field ("file", "image") whose value starts with assets:, depth first. The recursion
// is safe: parseDocument bounds the depth.
void collectAssetReferences(const Json& v, std::vector<std::string>& out) {
  if (v.is_array())
    for (const Json& child : v) collectAssetReferences(child, out);
  if (!v.is_object()) return;
  for (auto it = v.begin(); it != v.end(); ++it) {
    const Json& value = it.value();
    bool file_field = it.key() == "file" || it.key() == "image";
    if (file_field && value.is_string() && isAssetReference(value.get_ref<const std::string&>()))
      out.push_back(value.get<std::string>());
    else
      collectAssetReferences(value, out);
  }
}

}  // namespace

float keyTime(const Field& key, std::optional<float> previous) {
  Field time = key.required("time");
  const float t = time.number(Range::closed(0.0, 1e6));
  if (previous && !(t > *previous))
    time.fail("= {} must be greater than the previous key's time ({})", t, *previous);
  return t;
}

std::string resolvePath(const Context& ctx, const Field& field) {
  const std::string text = field.string();
  const bool asset = isAssetReference(text);
  fs::path path = asset ? fs::path(assetPath(field.where(), text)) : fs::path(text);
  if (!asset && path.is_relative()) {
    if (ctx.base_dir.empty())
      field.fail("= {}: a scene compiled into mirage can only refer to files as assets:<path>",
                 shortQuote(text, 200));
    path = fs::path(ctx.base_dir) / path;
  }
  if (isFile(path)) return path.string();
  if (asset)
    field.fail(
        "= {}: {} does not exist; run scripts/fetch-assets to download the assets (or "
        "set MIRAGE_ASSET_DIR to where they are)",
        shortQuote(text, 200), path.string());
  field.fail(
      "= {}: no such file ({}; relative paths are relative to the scene file's folder, "
      "assets:<path> to the asset directory)",
      shortQuote(text, 200), path.string());
}

int lookupName(const std::map<std::string, int>& names, const Field& field, const char* kind) {
  std::string name = field.string();
  if (auto it = names.find(name); it != names.end()) return it->second;
  std::string list;
  int shown = 0;
  for (const auto& [n, index] : names) {
    if (++shown > 24) {
      list += ", ...";
      break;
    }
    list += (list.empty() ? "" : ", ") + n;
  }
  std::string plural = std::string(kind) + (std::string_view(kind).ends_with("sh") ? "es" : "s");
  field.fail("= {}: no such {} (the scene's {}: {})", shortQuote(name), kind, plural,
             list.empty() ? "none" : list);
}

}  // namespace scene_json

std::string assetPath(const std::string& where, const std::string& reference) {
  std::string rest = reference.substr(std::string_view(kAssetPrefix).size());
  fs::path p(rest);
  bool inside = !rest.empty() && p.is_relative() && rest.find('\\') == std::string::npos;
  for (const fs::path& part : p) inside = inside && part != "..";
  if (!inside)
    throwInput(
        "{} = {}: an assets: path names a file inside the asset directory, e.g. "
        "assets:teapot/teapot.ply (no leading /, no ..)",
        where, scene_json::shortQuote(reference, 200));
  return (fs::path(assetDirectory()) / p).lexically_normal().string();
}

Scene parseSceneJson(const std::string& file, const std::string& text,
                     const std::string& base_dir) {
  Json doc = scene_json::parseDocument(file, text);
  Context ctx;
  ctx.file = file;
  ctx.base_dir = base_dir;
  Field root(ctx.file, doc, "");
  root.allowKeys({"name", "description", "environment", "light", "textures", "materials", "meshes",
                  "instances", "cameras", "reflections", "probes"},
                 "a scene file");
  Scene& s = ctx.scene;
  s.source = file;
  s.name = root.stringOr("name", fs::path(file).stem().string());
  if (auto d = root.optional("description")) {
    if (!d->json().is_string()) d->fail("= {}: expected a string", d->describe());
    s.description = d->json().get<std::string>();
  }
  if (auto env = root.optional("environment")) scene_json::parseEnvironment(ctx, *env);
  if (auto light = root.optional("light")) scene_json::parseLight(ctx, *light);

  std::vector<scene_json::TextureEntry> textures;
  if (auto list = root.optional("textures")) textures = scene_json::parseTextures(ctx, *list);
  if (auto list = root.optional("materials")) {
    for (const Field& f : list->items()) {
      Material m = scene_json::parseMaterial(ctx, f, textures);
      if (!ctx.material_index.emplace(m.name, int(s.materials.size())).second)
        f.required("name").fail("= {} is already the name of another material", shortQuote(m.name));
      s.materials.push_back(std::move(m));
    }
  }
  scene_json::loadTextures(ctx, textures);

  scene_json::parseMeshes(ctx, root);
  scene_json::parseInstances(ctx, root);

  if (auto list = root.optional("cameras")) {
    std::vector<Field> cams = list->items();
    for (size_t i = 0; i < cams.size(); ++i) {
      CameraDesc c = scene_json::parseCamera(cams[i], i);
      for (const CameraDesc& other : s.cameras)
        if (other.name == c.name)
          cams[i].fail("has the name {} of an earlier camera; names must differ",
                       shortQuote(c.name));
      s.cameras.push_back(std::move(c));
    }
  }
  if (auto list = root.optional("reflections")) s.reflections = scene_json::parseReflections(*list);
  if (auto list = root.optional("probes")) s.probes = scene_json::parseProbes(*list);
  s.ensureCamera();
  s.validate();
  for (const std::string& warning : probeWarnings(s)) spdlog::warn("{}", warning);
  return s;
}

Scene loadSceneJson(const std::string& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throwInput("{}: no such scene file{}", path, fs::exists(path, ec) ? " (it is a folder)" : "");
  auto size = fs::file_size(path, ec);
  if (ec) throwInput("{}: cannot read the scene file ({})", path, ec.message());
  if (size > scene_json::kMaxFileBytes)
    throwInput(
        "{}: the file has {} MiB; scene files are limited to {} MiB (geometry belongs in "
        "mesh files)",
        path, size >> 20, scene_json::kMaxFileBytes >> 20);
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) throwInput("{}: cannot read the scene file", path);
  fs::path base = fs::path(path).parent_path();
  return parseSceneJson(path, text.str(), base.empty() ? "." : base.string());
}

std::vector<std::string> sceneAssetReferences(const std::string& file, const std::string& text) {
  Json doc = scene_json::parseDocument(file, text);
  std::vector<std::string> out;
  scene_json::collectAssetReferences(doc, out);
  return out;
}

}  // namespace mirage
