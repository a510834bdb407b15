// `mirage scenes`: the scenes that can be rendered now, one a line on stdout; asset scenes not
// fetched yet go to stderr with the command that fetches them.
#include <cstdio>

#include "app/commands.h"
#include "scene/scene_loader.h"

namespace mirage::app {

Command addScenesCommand(CLI::App& parent) {
  Command cmd;
  cmd.app = parent.add_subcommand("scenes", "list the scenes that can be rendered");
  auto verbose = std::make_shared<bool>(false);
  cmd.app->add_flag("-v,--verbose", *verbose, "also print each scene's description");
  cmd.run = [verbose] {
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
