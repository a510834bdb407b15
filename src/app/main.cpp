// The `mirage` command-line tool: scenes, render, compare, bench.
#include <cstdio>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "app/commands.h"
#include "app/worker_threads.h"
#include "core/error.h"
#include "core/interrupt.h"

int main(int argc, char** argv) {
  using namespace mirage;
  const app::WorkerThreadsJoined workers;
  // Logs go to stderr so that stdout carries only results (`mirage scenes`).
  spdlog::set_default_logger(spdlog::stderr_color_mt("mirage"));
  spdlog::set_pattern("mirage: %^%l%$: %v");
  installInterruptHandlers();

  CLI::App app{"mirage: mirror reflections at interactive rates, measured against a ray tracer"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "mirage 0.1.0");
  std::vector<app::Command> commands = {app::addScenesCommand(app),  app::addRenderCommand(app),
                                        app::addCompareCommand(app), app::addBenchCommand(app),
                                        app::addViewCommand(app),    app::addAdviseCommand(app)};
  // A first word that is no option and no command: name it (CLI11 would only say that a
  // subcommand is required).
  if (argc > 1 && argv[1][0] != '-') {
    std::string word = argv[1], names;
    bool known = false;
    for (const app::Command& c : commands) {
      known = known || c.app->get_name() == word;
      names += (names.empty() ? "" : ", ") + c.app->get_name();
    }
    if (!known) {
      std::fprintf(stderr, "mirage: error: unknown command '%s' (allowed: %s)\n", word.c_str(),
                   names.c_str());
      return int(ExitCode::kBadInput);
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);  // prints the message
    return int(ExitCode::kBadInput);
  }
  try {
    for (const app::Command& c : commands)
      if (c.app->parsed()) return c.run();
  } catch (const Interrupted& e) {
    std::fprintf(stderr, "mirage: %s\n", e.what());
    return int(e.code());
  } catch (const Error& e) {
    std::fprintf(stderr, "mirage: error: %s\n", e.what());
    return int(e.code());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mirage: internal error: %s\n", e.what());
    return int(ExitCode::kFailure);
  }
  return int(ExitCode::kBadInput);
}
