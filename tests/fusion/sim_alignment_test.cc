// Temporal alignment on a real simulated sweep: every point carries its own
// capture time; moved to a camera time at constant velocity it must land on
// the true surfaces, where the same points taken as captured at the camera
// time do not.
#include <gtest/gtest.h>

#include "lvslam/fusion/feature_accumulator.h"
#include "lvslam/eval/line_accuracy.h"
#include "lvslam/sim/lidar_simulator.h"
#include "lvslam/sim/scenario.h"

namespace lvslam::fusion {
namespace {

// Distances to the true surfaces of the camera-frame features, mapped to the
// world with the true camera pose.
std::vector<double> surfaceDistances(const std::vector<SphereFeature>& features, const Eigen::Isometry3d& T_world_camera,
                                     const sim::World& world) {
  std::vector<double> d;
  for (const SphereFeature& f : features) d.push_back(world.distanceToSurface(T_world_camera * f.p_camera));
  return d;
}

TEST(TemporalAlignmentOnSimulatedSweep, UndoesTheRobotMotionWithPerPointTimes) {
  // The hall robot at speed (about 1 m/s) through a turn.
  const sim::Scenario scenario = sim::makeScenario("hall", {});
  const sim::LidarSimulator lidar(scenario);
  const double t0 = 20.0 + scenario.lidar.start_offset;
  const LidarScan scan = lidar.scanLidar(t0);
  ASSERT_TRUE(scan.has_time);
  const double t1 = t0 + lidar.sweepDuration();
  const double t_camera = t1;  // the paper aligns the sweep to the camera time t_{j+1} at its end

  std::vector<TimedFeature> timed, untimed;
  for (std::size_t i = 0; i < scan.points.size(); i += 7) {  // a subsample keeps the test fast
    TimedFeature f;
    f.p_lidar = scan.points[i].p.cast<double>();
    f.shape = FeatureShape::kPlanar;
    f.t = scan.pointTime(i);
    timed.push_back(f);
    f.t = t_camera;  // as if the whole sweep were captured at the camera time
    untimed.push_back(f);
  }
  // Constant velocity between the true poses at the sweep's ends.
  const ConstantVelocityMotion motion(t0, scenario.T_world_lidar(t0), t1, scenario.T_world_lidar(t1));
  const Eigen::Isometry3d T_world_camera = scenario.T_world_camera(t_camera);
  FeatureAccumulator aligned(1), naive(1);
  aligned.addScan(timed, motion);
  naive.addScan(untimed, motion);
  const auto d_aligned = surfaceDistances(aligned.inCameraFrame(T_world_camera), T_world_camera, scenario.world);
  const auto d_naive = surfaceDistances(naive.inCameraFrame(T_world_camera), T_world_camera, scenario.world);
  const double aligned_median = eval::quantile(d_aligned, 0.5), aligned_p90 = eval::quantile(d_aligned, 0.9);
  const double naive_median = eval::quantile(d_naive, 0.5), naive_p90 = eval::quantile(d_naive, 0.9);
  std::cout << "surface distance aligned median " << aligned_median << " p90 " << aligned_p90 << "; unaligned median "
            << naive_median << " p90 " << naive_p90 << " (" << d_aligned.size() << " points)\n";
  // Range noise is 1.5 cm along the ray: its median projection is below 1.5 cm.
  EXPECT_LT(aligned_median, 0.015);
  EXPECT_LT(aligned_p90, 0.04);
  // The motion over the sweep is much larger than the noise.
  EXPECT_GT(naive_p90, 3.0 * aligned_p90);
}

}  // namespace
}  // namespace lvslam::fusion
