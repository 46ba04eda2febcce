// The `loop:` section: values read, misspelt keys and unworkable values named.
#include <gtest/gtest.h>

#include "lvslam/loop/loop_config.h"
#include "support/temp_dir.h"

namespace lvslam::loop {
namespace {

LoopClosureConfig fromText(const std::string& text) {
  return loadLoopClosureConfig(YamlConfig::loadString(text, "test.yaml"));
}

TEST(LoopClosureConfig, ReadsValuesAndKeepsDefaultsWithoutTheSection) {
  const LoopClosureConfig c = fromText("loop:\n  enabled: false\n  scan_context:\n    rings: 10\n  max_rms: 0.1\n");
  EXPECT_FALSE(c.enabled);
  EXPECT_EQ(c.scan_context.rings, 10);
  EXPECT_EQ(c.scan_context.sectors, ScanContextConfig{}.sectors);
  EXPECT_EQ(c.max_rms, 0.1);
  EXPECT_TRUE(fromText("lidar: {}\n").enabled);
}

TEST(LoopClosureConfig, ShippedSimPresetEqualsTheDefaults) {
  const LoopClosureConfig shipped = loadLoopClosureConfig(YamlConfig::loadFile(LVSLAM_SOURCE_DIR "/config/sim.yaml"));
  const LoopClosureConfig defaults;
  EXPECT_EQ(shipped.enabled, defaults.enabled);
  EXPECT_EQ(shipped.keyframe_distance, defaults.keyframe_distance);
  EXPECT_EQ(shipped.scan_context.max_radius, defaults.scan_context.max_radius);
  EXPECT_EQ(shipped.max_descriptor_distance, defaults.max_descriptor_distance);
  EXPECT_EQ(shipped.max_rms, defaults.max_rms);
  EXPECT_EQ(shipped.min_inlier_ratio, defaults.min_inlier_ratio);
  EXPECT_EQ(shipped.odometry_gate_sigmas, defaults.odometry_gate_sigmas);
  EXPECT_EQ(shipped.loop_kernel, defaults.loop_kernel);
}

TEST(LoopClosureConfig, NamesTheFileAndTheKeyOfABadValue) {
  using testing::errorMessageOf;
  EXPECT_EQ(errorMessageOf([] { fromText("loop:\n  kernel: 3\n"); }), "test.yaml: key 'loop.kernel': unknown key (config/advanced.yaml lists every key)");
  EXPECT_EQ(errorMessageOf([] { fromText("loop:\n  max_descriptor_distance: 1.5\n"); }),
            "test.yaml: key 'loop.max_descriptor_distance': must be in (0, 1]");
  EXPECT_EQ(errorMessageOf([] { fromText("loop:\n  loop_kernel: 0\n"); }),
            "test.yaml: key 'loop.loop_kernel': must be positive");
  EXPECT_EQ(errorMessageOf([] { fromText("loop:\n  scan_context:\n    sectors: 1\n"); }),
            "test.yaml: key 'loop.scan_context.sectors': must be at least 2");
}

}  // namespace
}  // namespace lvslam::loop
