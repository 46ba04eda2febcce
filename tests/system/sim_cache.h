#pragma once
// Simulated sequences shared by the end-to-end tests: each is simulated once
// into LVSLAM_TEST_CACHE_DIR (the build tree) and reused by every later test
// process. gtest_discover_tests runs each TEST in its own process, possibly
// several at once, so creation holds an exclusive lock file and goes through
// "<name>.partial" renamed when complete. The name must say everything the
// options say (a changed simulator needs a clean cache folder).
#include <string>

#include "lvslam/sim/sim_options.h"

namespace lvslam::testing {

// The sequence folder of `name`, simulated with `options` if not cached yet.
std::string cachedSimulation(const std::string& name, const sim::SimOptions& options);

// The room scenario for `duration_s` seconds at `speed_scale` times its speed.
sim::SimOptions roomSimulation(double duration_s, int seed, double speed_scale = 1.0);
// Its sequence folder, cached under a name made from exactly those options
// ("room-8s-seed1", "room-2s-seed1-speed2").
std::string cachedRoom(double duration_s, int seed, double speed_scale = 1.0);

}  // namespace lvslam::testing
