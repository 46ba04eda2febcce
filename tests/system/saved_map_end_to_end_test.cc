// A map saved by one run localises another, end to end (`lvslam run
// --map-out`, then `--map-in`), in lidar mode as config/sim.yaml runs it:
// the map of two laps of the room (seed 1) written from the run reads back
// to the same bytes, and a run of another drive of the room (seed 2: its
// own start, noise and shake) finds its world in the map where the ground
// truth puts it.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include <gtest/gtest.h>

#include "lvslam/core/se3.h"
#include "lvslam/system/run_recording.h"
#include "lvslam/system/saved_map.h"
#include "support/trajectory_at.h"
#include "system/sim_cache.h"

namespace lvslam::system {
namespace {

constexpr double kDegree = M_PI / 180.0;

struct RoomRun {
  RunResult result;
  Trajectory ground_truth;  // T_sim_camera
};

RoomRun runRoom(const std::string& dir, const std::function<void(SystemConfig&)>& configure) {
  SystemConfig config = loadSystemConfig(YamlConfig::loadFile(std::string(LVSLAM_SOURCE_DIR) + "/config/sim.yaml"));
  config.mode = RunMode::kLidar;
  config.deterministic = true;
  configure(config);
  RecordingRequest request;
  request.sequence_dir = dir;
  Recording recording = openRecording(request);
  return {runRecording(recording, config), *recording.ground_truth};
}

// Where the run's world (its odometry frame) lies in the simulator's, from
// its first output pose and the ground truth there.
Eigen::Isometry3d T_sim_world(const RoomRun& run) {
  const StampedPose& first = run.result.output.trajectory.front();
  return lvslam::testing::poseAt(run.ground_truth, first.t) * first.T_world_frame.inverse();
}

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(SavedMapEndToEnd, AMapOfOneDriveOfTheRoomPlacesAnotherWhereTheTruthDoes) {
  const RoomRun mapping =
      runRoom(lvslam::testing::cachedRoom(42.0, 1, 2.0), [](SystemConfig& c) { c.keep_loop_keyframes = true; });
  const std::string path = (std::filesystem::temp_directory_path() / "lvslam_room_seed1.lvmap").string();
  const SavedMap saved =
      savedMapOf(mapping.result.records.loop_keyframes, mapping.result.output.loop, mapping.result.output.lines_world);
  ASSERT_GE(saved.keyframes.size(), 20u);
  writeSavedMap(path, saved);
  const std::string again = path + ".again";
  SavedMap read = readSavedMap(path);
  writeSavedMap(again, read);
  EXPECT_EQ(bytesOf(path), bytesOf(again));

  const auto keyframes = std::make_shared<const std::vector<loop::LoopKeyframe>>(std::move(read.keyframes));
  const RoomRun localised = runRoom(lvslam::testing::cachedRoom(10.0, 2, 2.0),
                                    [&keyframes](SystemConfig& c) { c.localize_in = keyframes; });
  ASSERT_TRUE(localised.result.output.loop.has_value());
  ASSERT_TRUE(localised.result.output.loop->map_localization.has_value());
  const loop::MapLocalization& l = *localised.result.output.loop->map_localization;
  ASSERT_TRUE(l.T_map_odom.has_value()) << l.matches.size() << " keyframes tried";
  // The map's frame is the mapping run's world.
  const Eigen::Isometry3d truth = T_sim_world(mapping).inverse() * T_sim_world(localised);
  const Eigen::Isometry3d error = truth.inverse() * *l.T_map_odom;
  std::printf("[ figures  ] %zu map keyframes; localised at %.2f s after %zu tries, %d agreeing; true placement "
              "%.3f m, %.2f deg; error %.4f m, %.3f deg\n",
              saved.keyframes.size(), l.localized_t - localised.ground_truth.front().t, l.matches.size(), l.agreeing,
              truth.translation().norm(), rotationAngle(truth) / kDegree, error.translation().norm(),
              rotationAngle(error) / kDegree);
  // Both runs' odometry errs about a centimetre over these drives, and one
  // registration against the map about as much.
  EXPECT_LT(error.translation().norm(), 0.05);
  EXPECT_LT(rotationAngle(error) / kDegree, 0.5);
  std::remove(path.c_str());
  std::remove(again.c_str());
}

}  // namespace
}  // namespace lvslam::system
