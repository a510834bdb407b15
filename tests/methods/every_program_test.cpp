// Every program of every method compiles and links: each method made and drawn on a scene with
// planar and curved reflectors and diffuse objects (gallery), at its defaults, at each value of
// each of its choice parameters, and at the numeric settings that change a shader's defines (the
// morph, self maps, the depth maps' tries). A shader that does not compile is a ShaderError, no
// fallback (the fixture fails a test in which a method fell back); and every shader file of
// src/ but the viewer's is compiled by one of them.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "core/embedded_files.h"
#include "gpu/program.h"
#include "methods/assignment.h"
#include "methods/frame.h"
#include "methods/method.h"
#include "scene/builtin_scenes.h"
#include "support/gl_test.h"

namespace mirage::test {
namespace {

using Params = std::map<std::string, std::string>;

class EveryProgram : public GlTest {};

// The parameter sets a method is drawn with: its defaults, then one choice parameter at a time at
// each of its other values, then the numeric settings behind defines.
std::vector<Params> variants(const MethodEntry& entry) {
  std::vector<Params> out{{}};
  for (const ParamSpec& p : entry.info.params)
    if (p.type == ParamSpec::Type::kChoice)
      for (const std::string& c : p.choices)
        if (c != p.default_value) out.push_back({{p.name, c}});
  const std::string& name = entry.info.name;
  if (name == "billboard" || name == "depthmap") out.push_back({{"morph-height", "0.5"}});
  if (name == "depthmap") {
    out.push_back({{"self-maps", "2"}});
    out.push_back({{"depthmap-tries", "1"}});
  }
  if (name == "mixed")
    out.push_back({{kAssignParam,
                    "mirror-back=planar;mirror-left=zexel;mirror-sphere=hybrid;"
                    "mirror-teapot=depthmap;*=ssr"}});
  return out;
}

std::string text(const Params& params) {
  std::string s;
  for (const auto& [k, v] : params) s += " --" + k + " " + v;
  return s.empty() ? " (defaults)" : s;
}

TEST_F(EveryProgram, CompilesAndLinksInEveryVariantOfEveryMethod) {
  const std::map<std::string, long long> before = gpu::compiledShaderFiles();
  const Scene scene = makeBuiltinScene("gallery");
  const ivec2 size{48, 32};
  FrameRenderer renderer(scene, size);
  int drawn = 0;
  for (const MethodEntry& entry : methodRegistry()) {
    if (entry.info.name == "raytrace") continue;  // no program
    for (const Params& params : variants(entry)) {
      SCOPED_TRACE(entry.info.name + text(params));
      FrameSettings settings;
      std::unique_ptr<Method> m;
      ASSERT_NO_THROW({
        m = renderer.createMethod(entry.info.name, params, settings);
        renderer.render(*m, View(scene.camera(), size), 0.0f, settings);
      });
      EXPECT_EQ(m->fallbackReason(), "");
      ++drawn;
    }
  }
  EXPECT_GT(drawn, 40) << "variants drawn";
  // Every shader file reached (compiled again here, whatever other tests compiled before).
  const std::map<std::string, long long> after = gpu::compiledShaderFiles();
  for (const embedded::EmbeddedFile& f : embedded::files()) {
    const std::string path = f.path;
    const bool stage = path.ends_with(".frag") || path.ends_with(".vert") || path.ends_with(".comp");
    if (!stage || path.starts_with("viewer/")) continue;  // the viewer's own: tests/viewer/
    if (path == "shading/proxy_check.comp") continue;     // the proxies' test shader
    const auto was = before.find(path);
    const auto is = after.find(path);
    EXPECT_TRUE(is != after.end() && (was == before.end() || is->second > was->second))
        << path << " was compiled by no variant";
  }
}

}  // namespace
}  // namespace mirage::test
