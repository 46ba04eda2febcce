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

TEST(LoopClosureConfig, NamesTheFileAndTheKeyOfABadValue) {
  using testing::errorMessageOf;
  EXPECT_EQ(errorMessageOf([] { fromText("loop:\n  kernel: 3\n"); }), "test.yaml: key 'loop': unknown key 'kernel'");
  EXPECT_EQ(errorMessageOf([] { fromText("loop:\n  max_descriptor_distance: 1.5\n"); }),
            "test.yaml: key 'loop.max_descriptor_distance': must be in (0, 1]");
  EXPECT_EQ(errorMessageOf([] { fromText("loop:\n  loop_kernel: 0\n"); }),
            "test.yaml: key 'loop.loop_kernel': must be positive");
  EXPECT_EQ(errorMessageOf([] { fromText("loop:\n  scan_context:\n    sectors: 1\n"); }),
            "test.yaml: key 'loop.scan_context.sectors': must be at least 2");
}

}  // namespace
}  // namespace lvslam::loop
