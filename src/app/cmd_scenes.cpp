// `mirage scenes`: the scenes that can be rendered now, one a line on stdout; asset scenes not
// fetched yet go to stderr with the command that fetches them. Given scene names (or files), it
// loads them and lists their instances with each one's layer (scene/layers.h) instead.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands.h"
#include "scene/layers.h"
#include "scene/probes.h"
#include "scene/scene_loader.h"

namespace mirage::app {

namespace {

// The scene's own reflection probes (scene/probes.h), in blend order, with the reflectors each
// influences; none: one probe at each reflector.
void printProbes(const Scene& scene) {
  if (scene.probes.empty()) {
    std::printf("  probes: one at each reflector's centre (the scene gives none)\n");
    return;
  }
  std::printf("  probes, in blend order:\n");
  std::printf("  %-28s %8s %-9s %8s  %s\n", "probe", "priority", "influence", "blend",
              "influences");
  for (int k : probeBlendOrder(scene.probes)) {
    const ReflectionProbe& p = scene.probes[size_t(k)];
    std::string influenced;
    for (int r : reflectorsInfluenced(scene, p))
      influenced += (influenced.empty() ? "" : ", ") + scene.instances[size_t(r)].name;
    std::printf("  %-28s %8d %-9s %8g  %s\n", p.name.c_str(), p.priority,
                p.influence.sphere ? "sphere" : "box", double(p.blend_distance),
                influenced.empty() ? "(none)" : influenced.c_str());
  }
}

// One scene's instances: name, layer and why, triangles, and the planar parts of the
// environment's instances; -v adds the description.
void printInstances(const std::string& spec, bool verbose) {
  const Scene scene = loadScene(spec);
  const SceneLayers layers = sceneLayers(scene);
  std::printf("%s: %zu instances, %zu triangles\n", scene.name.c_str(), scene.instances.size(),
              scene.triangleCount());
  if (verbose && !scene.description.empty()) std::printf("  %s\n", scene.description.c_str());
  std::printf("  %-28s %-11s %9s %6s  %s\n", "instance", "layer", "triangles", "planes", "why");
  for (int i = 0; i < int(scene.instances.size()); ++i) {
    const Instance& instance = scene.instances[size_t(i)];
    const bool environment = layers.environment(i);
    const std::string planes =
        environment ? std::to_string(layers.planesOf(i).size()) : std::string("-");
    const bool rest = std::find(layers.rest.begin(), layers.rest.end(), i) != layers.rest.end();
    std::printf("  %-28s %-11s %9zu %6s  %s%s\n", instance.name.c_str(), layers.name(i),
                scene.meshes[size_t(instance.mesh)].triangleCount(), planes.c_str(),
                layers.instances[size_t(i)].why.c_str(),
                environment && rest ? "; the rest through probes" : "");
  }
  printProbes(scene);
}

}  // namespace

Command addScenesCommand(CLI::App& parent) {
  Command cmd;
  cmd.app = parent.add_subcommand(
      "scenes", "list the scenes that can be rendered, or the instances and layers of some");
  auto verbose = std::make_shared<bool>(false);
  auto names = std::make_shared<std::vector<std::string>>();
  cmd.app->add_flag("-v,--verbose", *verbose, "also print each scene's description");
  cmd.app->add_option("scenes", *names,
                      "scenes (names or files) whose instances and layers to list");
  cmd.run = [verbose, names] {
    if (!names->empty()) {
      for (const std::string& name : *names) printInstances(name, *verbose);
      return 0;
    }
    for (const SceneListing& s : listScenes()) {
      if (s.available) {
        if (*verbose)
          std::printf("%-22s %s\n", s.name.c_str(), s.description.c_str());
        else
          std::printf("%s\n", s.name.c_str());
      } else {
        std::fprintf(stderr, "%s (not available: %s)\n", s.name.c_str(), s.missing.c_str());
      }
    }
    return 0;
  };
  return cmd;
}

}  // namespace mirage::app
