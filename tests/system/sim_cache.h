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

}  // namespace lvslam::testing
