#pragma once
// The clean input of the end-to-end CLI tests: a 3 s simulated room,
// simulated once per build tree (../system/sim_cache.h) and copied into a
// test's folder as `seq`, to be broken or changed there.
#include <filesystem>
#include <string>

#include "support/temp_dir.h"
#include "system/sim_cache.h"

namespace lvslam::testing {

inline std::string cleanSequence(const TempDir& dir) {
  sim::SimOptions options;
  options.scenario = "room";
  options.duration = 3.0;
  const std::string cached = cachedSimulation("faults-room-3s", options);
  std::filesystem::copy(cached, dir.path() / "seq", std::filesystem::copy_options::recursive);
  return "seq";
}

}  // namespace lvslam::testing
