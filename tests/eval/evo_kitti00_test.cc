// evo's own published results on KITTI 00 (ORB-SLAM2 estimate), which an
// evaluation following evo's definitions must reproduce.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "lvslam/eval/evaluate.h"
#include "lvslam/io/tum.h"

namespace lvslam::eval {
namespace {

const std::string kEvoDir = std::string(LVSLAM_SHARED_DATA_DIR) + "/evo";

// evo's figures carry 7-8 significant digits.
void expectRelative(double actual, double expected) {
  EXPECT_NEAR(actual, expected, 1e-6 * expected) << "expected " << expected;
}

class EvoKitti00 : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kEvoDir + "/KITTI_00_gt.txt"))
      GTEST_SKIP() << "shared test data missing: " << kEvoDir << " (see ../shared/data/README.md)";
    const std::string times = kEvoDir + "/KITTI_00_gt_times.txt";
    gt_ = readKittiPoses(kEvoDir + "/KITTI_00_gt.txt", times);
    est_ = readKittiPoses(kEvoDir + "/KITTI_00_ORB.txt", times);
  }
  Trajectory gt_;
  Trajectory est_;
};

TEST_F(EvoKitti00, AllPosesAssociate) {
  ASSERT_EQ(gt_.size(), 4541u);
  EXPECT_EQ(evaluate(gt_, est_).pairs, 4541u);
}

TEST_F(EvoKitti00, ApeTranslationSe3MatchesEvo) {
  const ErrorStatistics s = evaluate(gt_, est_).ate.stats;
  expectRelative(s.rmse, 1.3034497);
  expectRelative(s.mean, 1.1569971);
  expectRelative(s.median, 1.0656248);
  expectRelative(s.max, 3.5879491);
  expectRelative(s.min, 0.0693132);
  expectRelative(s.std_dev, 0.6002823);
}

TEST_F(EvoKitti00, RpeTranslation10mMatchesEvo) {
  EvalOptions options;
  options.rpe_delta_m = 10.0;
  const ErrorStatistics s = evaluate(gt_, est_, options).rpe.translation;
  expectRelative(s.rmse, 0.2262613);
  expectRelative(s.mean, 0.1690174);
  expectRelative(s.median, 0.1384843);
  expectRelative(s.max, 1.2722091);
  expectRelative(s.min, 0.0253227);
  expectRelative(s.std_dev, 0.1504238);
}

}  // namespace
}  // namespace lvslam::eval
