// The subcommands of `mirage`, one file each. Each registers its options on the parent app and
// returns the function that runs it after parsing.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace mirage::app {

struct Command {
  CLI::App* app = nullptr;
  std::function<int()> run;  // returns the exit code
};

Command addScenesCommand(CLI::App& parent);
Command addRenderCommand(CLI::App& parent);
Command addCompareCommand(CLI::App& parent);
Command addBenchCommand(CLI::App& parent);
Command addViewCommand(CLI::App& parent);
Command addAdviseCommand(CLI::App& parent);

}  // namespace mirage::app
