#include "lvslam/io/intrinsics_check.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace lvslam {
namespace {

TEST(IntrinsicsCheck, ARealCameraGivesNoWarning) {
  EXPECT_TRUE(intrinsicsWarnings(PinholeCamera(640, 480, 617.97, 616.45, 327.71, 253.98), "s.yaml").empty());
  EXPECT_TRUE(intrinsicsWarnings(PinholeCamera(1241, 376, 718.86, 718.86, 607.19, 185.22), "s.yaml").empty());
}

TEST(IntrinsicsCheck, TinyAndHugeFocalLengthsAreNamed) {
  const std::vector<std::string> tiny = intrinsicsWarnings(PinholeCamera(640, 480, 1e-9, 600, 320, 240), "seq/s.yaml");
  ASSERT_EQ(tiny.size(), 1u);
  EXPECT_NE(tiny[0].find("seq/s.yaml: key 'camera.intrinsics': fx = 1e-09 gives the 640-pixel image width a field "
                         "of view of 180 deg"),
            std::string::npos)
      << tiny[0];
  const std::vector<std::string> huge = intrinsicsWarnings(PinholeCamera(640, 480, 600, 1e300, 320, 240), "s.yaml");
  ASSERT_EQ(huge.size(), 1u);
  EXPECT_NE(huge[0].find("fy = 1e+300"), std::string::npos) << huge[0];
}

TEST(IntrinsicsCheck, PrincipalPointOutsideTheImage) {
  const std::vector<std::string> w = intrinsicsWarnings(PinholeCamera(640, 480, 600, 600, 3200, 240), "s.yaml");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("principal point (3200, 240) lies outside the 640x480 image"), std::string::npos) << w[0];
}

}  // namespace
}  // namespace lvslam
