#pragma once
// Each subcommand (apps/cmd_<name>.cc) registers itself on the CLI and stores
// what to run once the command line has been parsed. Exit codes: 0 ok, 1 the
// job failed, 2 bad input or usage (lvslam::Error).
#include <functional>

#include <CLI/CLI.hpp>

namespace lvslam::apps {

using CommandAction = std::function<int()>;

// One line per subcommand; main.cc calls each.
void addEvalCommand(CLI::App& app, CommandAction& action);
void addConvertCommand(CLI::App& app, CommandAction& action);
void addSimulateCommand(CLI::App& app, CommandAction& action);
void addRunCommand(CLI::App& app, CommandAction& action);
void addOverlayCommand(CLI::App& app, CommandAction& action);
void addBenchCommand(CLI::App& app, CommandAction& action);
void addReportCommand(CLI::App& app, CommandAction& action);

}  // namespace lvslam::apps
