#include <exception>
#include <filesystem>
#include <iostream>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "command.h"
#include "lvslam/core/error.h"

int main(int argc, char** argv) {
  // Warnings go to stderr with the errors; stdout carries only results.
  spdlog::set_default_logger(spdlog::stderr_color_mt("lvslam"));
  CLI::App app{"lvslam: tightly-coupled LiDAR-visual SLAM on geometric features"};
  app.require_subcommand(1);
  lvslam::apps::CommandAction action;
  lvslam::apps::addEvalCommand(app, action);
  lvslam::apps::addConvertCommand(app, action);
  lvslam::apps::addSimulateCommand(app, action);
  lvslam::apps::addRunCommand(app, action);
  lvslam::apps::addOverlayCommand(app, action);
  lvslam::apps::addBenchCommand(app, action);
  lvslam::apps::addReportCommand(app, action);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    return action ? action() : 0;
  } catch (const lvslam::Error& e) {
    std::cerr << "lvslam: error: " << e.what() << "\n";
    return 2;
  } catch (const std::filesystem::filesystem_error& e) {
    // A path the system refused (permission, loop, name too long) that no
    // reader turned into an lvslam::Error yet: still bad input, named.
    std::cerr << "lvslam: error: " << e.path1().string() << ": " << e.code().message() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "lvslam: failed: " << e.what() << "\n";
    return 1;
  }
}
