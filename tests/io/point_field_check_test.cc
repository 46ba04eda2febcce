#include "lvslam/io/point_field_check.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace lvslam {
namespace {

TEST(PointFieldCheck, AllKnownWithTimeGivesNoWarning) {
  EXPECT_TRUE(pointFieldWarnings({"x", "y", "z", "intensity", "time", "ring"}, "s.yaml").empty());
  EXPECT_TRUE(pointFieldWarnings({"x", "y", "z", "time", "reflectivity", "t_ns_raw"}, "s.yaml").empty())
      << "unknown names far from any known one are the sensor's own";
}

TEST(PointFieldCheck, AMisspeltTimeIsNamedWithTheNearestKnownName) {
  const std::vector<std::string> w = pointFieldWarnings({"x", "y", "z", "intensity", "tiem", "ring"}, "seq/s.yaml");
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(w[0], "seq/s.yaml: key 'lidar.point_fields': unknown field 'tiem' is skipped; did you mean 'time'?");
  EXPECT_NE(w[1].find("no per-point 'time'"), std::string::npos) << w[1];
  const std::vector<std::string> r = pointFieldWarnings({"x", "y", "z", "intensty", "time", "rnig"}, "s.yaml");
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NE(r[0].find("'intensty' is skipped; did you mean 'intensity'"), std::string::npos) << r[0];
  EXPECT_NE(r[1].find("'rnig' is skipped; did you mean 'ring'"), std::string::npos) << r[1];
}

TEST(PointFieldCheck, NoTimeAtAllIsOneWarning) {
  const std::vector<std::string> w = pointFieldWarnings({"x", "y", "z", "intensity"}, "kitti/sequence.yaml");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("kitti/sequence.yaml: key 'lidar.point_fields': no per-point 'time': the scans are not "
                      "deskewed"),
            std::string::npos)
      << w[0];
}

}  // namespace
}  // namespace lvslam
