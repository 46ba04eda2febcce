// VisualSlam on short simulated room sequences rendered in memory: metric
// initialisation from the renderer's exact depth and tracking under an ATE
// bound, loss on black frames and re-initialisation in a new map, and the
// fusion-line face.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"
#include "lvslam/eval/evaluate.h"
#include "lvslam/visual/visual_slam.h"
#include "visual/rendered_room.h"

namespace lvslam::visual {
namespace {

class VisualSlamTest : public testing::RenderedRoomTest {};

// With LiDAR depth under its keypoints the first frame starts the map alone
// (one point per keypoint with a depth, on its ray); every frame is tracked.
TEST_F(VisualSlamTest, WithDepthTheFirstFrameStartsAMetricMapAndTracksWithinCentimetres) {
  VisualSlam slam(VisualSlamConfig{}, camera());
  Trajectory estimate, truth;
  std::vector<VisualFrameResult> results;
  run(slam, 0, 1, estimate, truth, &results);
  ASSERT_EQ(results.size(), 1u);
  EXPECT_TRUE(results[0].pose_valid);
  EXPECT_TRUE(results[0].keyframe);
  EXPECT_TRUE(results[0].metric);
  EXPECT_FALSE(results[0].initial_reference.has_value());
  EXPECT_TRUE(results[0].T_world_camera.isApprox(Eigen::Isometry3d::Identity()));
  const Keyframe& first = slam.map().keyframes().begin()->second;
  const cv::Mat& depth = (*frames_)[0].depth;
  std::vector<double> depth_errors;  // relative, against the true depth at the keypoint
  for (size_t i = 0; i < first.point_landmark.size(); ++i) {
    if (first.point_landmark[i] < 0) continue;
    const Eigen::Vector3d p = slam.map().point(first.point_landmark[i]).p_world;  // the first camera is the world
    const cv::Point2f& px = first.features.keypoints[i].pt;
    const double z = depth.at<float>(static_cast<int>(std::lround(px.y)), static_cast<int>(std::lround(px.x)));
    depth_errors.push_back(std::abs(p.z() / z - 1.0));
    EXPECT_NEAR(camera().fx() * p.x() / p.z() + camera().cx(), first.features.points[i].x(), 1e-6);
  }
  ASSERT_GE(depth_errors.size(), static_cast<size_t>(VisualSlamConfig{}.modules.initializer.min_triangulated));
  // Read through a local plane of 5 % tolerance: most within it, the median
  // close to exact; a corner on an occluding edge may take either surface.
  std::sort(depth_errors.begin(), depth_errors.end());
  EXPECT_LT(depth_errors[depth_errors.size() / 2], 0.01);
  EXPECT_LT(depth_errors[depth_errors.size() * 9 / 10], 0.05);
  run(slam, 1, frames_->size(), estimate, truth, &results);
  EXPECT_TRUE(std::all_of(results.begin(), results.end(), [](const auto& r) { return r.pose_valid && r.metric; }));
  EXPECT_EQ(slam.state(), TrackingState::kTracking);
  EXPECT_GT(results.back().health.tracked_points, 50);
  EXPECT_GT(slam.map().keyframes().size(), 2u);
  EXPECT_GT(slam.map().lines().size(), 0u);
  EXPECT_LT(se3Accuracy(truth, estimate).ate.stats.rmse, 0.05);
  // The path is long enough that a wrong scale would show in the ATE.
  const double path = (truth.back().T_world_frame.translation() - truth.front().T_world_frame.translation()).norm();
  EXPECT_GT(path, 0.5);
}

// Without depth two views with parallax start the map (median depth 1, not
// metric); from then on every frame is tracked and the path fits the truth
// up to scale.
TEST_F(VisualSlamTest, WithoutDepthTwoViewsStartAMapUpToScale) {
  VisualSlam slam(VisualSlamConfig{}, camera());
  Trajectory estimate, truth;
  std::vector<VisualFrameResult> results;
  for (const RenderedFrame& f : *frames_) {
    results.push_back(slam.track(f.image));
    if (!results.back().pose_valid) continue;
    estimate.push_back({results.back().timestamp, results.back().T_world_camera});
    truth.push_back({results.back().timestamp, f.T_world_camera});
  }
  EXPECT_FALSE(results.front().pose_valid);
  const auto first = std::find_if(results.begin(), results.end(), [](const auto& r) { return r.pose_valid; });
  ASSERT_NE(first, results.end());
  EXPECT_TRUE(first->initial_reference.has_value());
  EXPECT_TRUE(std::all_of(first, results.end(), [](const auto& r) { return r.pose_valid && !r.metric; }));
  ASSERT_GE(estimate.size(), frames_->size() / 2);
  eval::EvalOptions options;
  options.alignment = eval::Alignment::kSim3;
  const eval::EvalResult sim3 = eval::evaluate(truth, estimate, options);
  EXPECT_LT(sim3.ate.stats.rmse, 0.05);
}

TEST_F(VisualSlamTest, BlackFramesLoseTrackingThenANewMapStarts) {
  VisualSlamConfig config;
  config.relocalize_frames = 2;
  VisualSlam slam(config, camera());
  Trajectory estimate, truth;
  const size_t half = frames_->size() / 2;
  run(slam, 0, half, estimate, truth);
  ASSERT_EQ(slam.state(), TrackingState::kTracking);
  ASSERT_EQ(slam.mapId(), 0);
  for (int k = 0; k < 5; ++k) {
    const ImageFrame black{(*frames_)[half].image.timestamp - 0.01 * (5 - k),
                           cv::Mat::zeros(camera().height(), camera().width(), CV_8UC1)};
    const VisualFrameResult r = slam.track(black);
    EXPECT_EQ(r.state, TrackingState::kLost);
    EXPECT_FALSE(r.pose_valid);
    EXPECT_LT(r.health.brightness, 1.0);
  }
  Trajectory after, after_truth;
  run(slam, half, frames_->size(), after, after_truth);
  EXPECT_EQ(slam.state(), TrackingState::kTracking);
  EXPECT_EQ(slam.mapId(), 1);
  ASSERT_GE(after.size(), 5u);
  EXPECT_LT(se3Accuracy(after_truth, after).ate.stats.rmse, 0.05);
}

// A short blackout while the camera keeps moving: the frame is relocalised
// into the old map (same map id, same world frame), not re-initialised.
TEST_F(VisualSlamTest, ABlackoutIsRelocalisedIntoTheOldMap) {
  VisualSlam slam(VisualSlamConfig{}, camera());
  Trajectory estimate, truth;
  const size_t half = frames_->size() / 2, blackout = 5;
  run(slam, 0, half, estimate, truth);
  ASSERT_EQ(slam.state(), TrackingState::kTracking);
  for (size_t i = half; i < half + blackout; ++i) {
    const ImageFrame black{(*frames_)[i].image.timestamp, cv::Mat::zeros(camera().height(), camera().width(), CV_8UC1)};
    EXPECT_FALSE(slam.track(black).pose_valid);
  }
  EXPECT_EQ(slam.state(), TrackingState::kLost);
  std::vector<VisualFrameResult> results;
  Trajectory after, after_truth;
  run(slam, half + blackout, frames_->size(), after, after_truth, &results);
  ASSERT_FALSE(results.empty());
  EXPECT_TRUE(results.front().pose_valid);  // the first frame after the blackout
  EXPECT_TRUE(std::all_of(results.begin(), results.end(), [](const auto& r) { return r.map_id == 0; }));
  EXPECT_EQ(slam.mapId(), 0);
  EXPECT_EQ(slam.state(), TrackingState::kTracking);
  // One world frame before and after: a single SE3 alignment fits both parts.
  for (const StampedPose& p : after) estimate.push_back(p);
  for (const StampedPose& p : after_truth) truth.push_back(p);
  const eval::EvalResult accuracy = se3Accuracy(truth, estimate);
  EXPECT_LT(accuracy.ate.stats.rmse, 0.05);
  EXPECT_LT(accuracy.ate.stats.max, 0.1);
}

TEST_F(VisualSlamTest, FusionLineBecomesALandmarkWithItsPluckerCoordinates) {
  VisualSlam slam(VisualSlamConfig{}, camera());
  Trajectory estimate, truth;
  run(slam, 0, frames_->size() / 2, estimate, truth);
  ASSERT_EQ(slam.state(), TrackingState::kTracking);
  const std::vector<ImageLineSegment> segments = slam.lineSegments();
  ASSERT_FALSE(segments.empty());
  const Eigen::Isometry3d T_world_camera = estimate.back().T_world_frame;
  const Eigen::Vector3d A(0.3, -0.2, 2.0), B(0.9, 0.4, 3.5), direction = (B - A).normalized();
  // Pick a segment without a landmark, so that a new landmark is created.
  int landmark = -1;
  const size_t lines_before = slam.map().lines().size();
  for (size_t s = 0; s < segments.size() && landmark < 0; ++s) {
    const int id = slam.addFusionLine(static_cast<int>(s), A, B, direction);
    if (slam.map().lines().size() > lines_before) landmark = id;
  }
  ASSERT_GE(landmark, 0);
  const LineLandmark& line = slam.map().line(landmark);
  const Eigen::Vector3d A_w = T_world_camera * A, B_w = T_world_camera * B;
  EXPECT_TRUE(line.from_fusion);
  EXPECT_LT((line.line_world.m - A_w.cross(B_w)).norm(), 1e-9);
  EXPECT_LT((line.line_world.d - (B_w - A_w)).norm(), 1e-9);
  ASSERT_TRUE(line.fusion_direction.has_value());
  EXPECT_LT((*line.fusion_direction - T_world_camera.linear() * direction).norm(), 1e-9);
  EXPECT_LT((line.start_world - A_w).norm(), 1e-9);
  // Bad input is an error, not a landmark.
  const Eigen::Vector3d nan(std::nan(""), 0.0, 1.0);
  EXPECT_THROW(slam.addFusionLine(0, nan, B, direction), Error);
  EXPECT_THROW(slam.addFusionLine(0, A, A, direction), Error);
  EXPECT_THROW(slam.addFusionLine(static_cast<int>(segments.size()), A, B, direction), Error);
  // The tracker keeps working with the fusion landmark in its local map.
  run(slam, frames_->size() / 2, frames_->size() / 2 + 5, estimate, truth);
  EXPECT_EQ(slam.state(), TrackingState::kTracking);
}

// LiDAR keypoint depths (here the renderer's exact depth at the keypoint):
// the face's errors, storage on keyframes only, and points made from them.
TEST_F(VisualSlamTest, KeypointDepthsAreStoredOnKeyframesAndMakePoints) {
  VisualSlamConfig config;
  config.triangulation.create_depth_points = true;
  VisualSlam slam(config, camera());
  const auto depthAt = [](const cv::Mat& depth, const Eigen::Vector2d& px) {
    const int u = static_cast<int>(std::lround(px.x())), v = static_cast<int>(std::lround(px.y()));
    const bool inside = u >= 0 && v >= 0 && u < depth.cols && v < depth.rows;
    return inside ? static_cast<double>(depth.at<float>(v, u)) : std::nan("");
  };
  int keyframes = 0, non_keyframes = 0;
  for (size_t i = 0; i < frames_->size() && keyframes < 3; ++i) {
    const RenderedFrame& f = (*frames_)[i];
    if (slam.needsDepthHints()) slam.setDepthHints(depthHints(f.depth));
    const VisualFrameResult r = slam.track(f.image);
    const std::vector<Eigen::Vector2d> pixels = slam.keypointPixels();
    ASSERT_EQ(pixels.size(), static_cast<size_t>(r.health.keypoints));
    EXPECT_THROW(slam.setKeypointDepths(std::vector<double>(pixels.size() + 1, 2.0)), Error);
    EXPECT_EQ(slam.currentIsKeyframe(), r.keyframe);
    std::vector<double> depths;
    for (const Eigen::Vector2d& px : pixels) depths.push_back(depthAt(f.depth, px));
    depths.at(0) = -1.0;  // no depth, not an error
    if (!r.keyframe) {
      const size_t points = slam.map().points().size();
      slam.setKeypointDepths(depths);  // ignored
      EXPECT_EQ(slam.map().points().size(), points);
      non_keyframes += r.pose_valid;
      continue;
    }
    ++keyframes;
    const int id = slam.map().keyframes().rbegin()->first;  // the current frame's keyframe
    const std::vector<int> before = slam.map().keyframe(id).point_landmark;
    slam.setKeypointDepths(depths);
    const Keyframe& k = slam.map().keyframe(id);
    ASSERT_EQ(k.keypoint_depth.size(), depths.size());
    EXPECT_TRUE(std::isnan(k.keypoint_depth[0]));
    int created = 0;
    for (size_t j = 1; j < depths.size(); ++j) {
      if (std::isfinite(depths[j]) && depths[j] > 0.0) {
        EXPECT_EQ(k.keypoint_depth[j], depths[j]);
      }
      if (before[j] >= 0 || k.point_landmark[j] < 0) continue;
      // A new point lies on the keypoint's ray at its depth.
      ++created;
      const Eigen::Vector3d p_c = k.T_camera_world * slam.map().point(k.point_landmark[j]).p_world;
      EXPECT_NEAR(p_c.z(), depths[j], 1e-9);
      EXPECT_NEAR(camera().fx() * p_c.x() / p_c.z() + camera().cx(), k.features.points[j].x(), 1e-6);
    }
    // The map's first keyframe made a point of every keypoint with a depth
    // already (one-view start); later ones add what triangulation missed.
    if (keyframes == 1) EXPECT_EQ(created, 0);
    else EXPECT_GT(created, 0);
    EXPECT_LE(created, config.triangulation.max_depth_points);
  }
  EXPECT_EQ(keyframes, 3);
  EXPECT_GT(non_keyframes, 0);
}

// The pipeline extracts on another thread and hands the result to track():
// the same poses as extracting inside track(); features of another camera
// size are refused.
TEST_F(VisualSlamTest, TrackingAnExtractedImageEqualsTrackingTheImage) {
  VisualSlam whole(VisualSlamConfig{}, camera());
  VisualSlam split(VisualSlamConfig{}, camera());
  FeatureExtractor extractor(VisualSlamConfig{}.modules.features, camera());
  int posed = 0;
  for (size_t i = 0; i < 40 && i < frames_->size(); ++i) {
    const RenderedFrame& f = (*frames_)[i];
    if (whole.needsDepthHints()) whole.setDepthHints(depthHints(f.depth));
    if (split.needsDepthHints()) split.setDepthHints(depthHints(f.depth));
    const VisualFrameResult a = whole.track(f.image);
    const VisualFrameResult b = split.track(extractImage(extractor, f.image));
    ASSERT_EQ(a.pose_valid, b.pose_valid) << "frame " << i;
    EXPECT_EQ(a.health.keypoints, b.health.keypoints);
    EXPECT_EQ(a.health.brightness, b.health.brightness);
    if (!a.pose_valid) continue;
    ++posed;
    EXPECT_TRUE(a.T_world_camera.isApprox(b.T_world_camera, 1e-12)) << "frame " << i;
  }
  EXPECT_GE(posed, 15);
  ExtractedImage foreign;
  foreign.features.width = camera().width() / 2;
  foreign.features.height = camera().height() / 2;
  EXPECT_THROW(split.track(foreign), Error);
}

// LiDAR poses arrive a few frames late; keyframes at their times take them
// (the initial pair's first view too), others are dropped; switched off,
// none is taken.
TEST_F(VisualSlamTest, LidarPosesReachTheKeyframesOfTheirTimes) {
  for (const bool enabled : {true, false}) {
    VisualSlamConfig config;
    config.modules.use_lidar_pose_priors = enabled;
    VisualSlam slam(config, camera());
    Vector6d xi;
    xi << 2.0, 1.0, 0.0, 0.0, 0.0, 0.7;
    const Eigen::Isometry3d T_odom_world = expSE3(xi);
    const size_t lag = 3, n = std::min<size_t>(45, frames_->size());
    for (size_t i = 0; i < n; ++i) {
      const RenderedFrame& f = (*frames_)[i];
      if (slam.needsDepthHints()) slam.setDepthHints(depthHints(f.depth));
      slam.track(f.image);
      if (i >= lag) {
        const RenderedFrame& late = (*frames_)[i - lag];
        slam.addLidarPose(late.image.timestamp, T_odom_world * late.T_world_camera);
      }
    }
    int with_pose = 0, keyframes = 0;
    for (const auto& [id, k] : slam.map().keyframes()) {
      ++keyframes;
      if (!k.T_odom_camera) continue;
      ++with_pose;
      // Truth in, truth out: the prior equals the keyframe pose up to the visual error.
      const Eigen::Isometry3d prior = *slam.map().odometryPrior(id);
      EXPECT_LT((prior.inverse().translation() - k.T_camera_world.inverse().translation()).norm(), 0.05);
    }
    ASSERT_GT(keyframes, 3);
    if (enabled) {
      EXPECT_GE(with_pose, keyframes - 1);  // the newest may still wait for its pose
      EXPECT_TRUE(slam.map().keyframes().begin()->second.T_odom_camera.has_value());
    } else {
      EXPECT_EQ(with_pose, 0);
    }
  }
  VisualSlam slam(VisualSlamConfig{}, camera());
  Eigen::Isometry3d nan_pose = Eigen::Isometry3d::Identity();
  nan_pose.translation().x() = std::nan("");
  EXPECT_THROW(slam.addLidarPose(1.0, nan_pose), Error);
}

TEST(ImageStatisticsTest, BrightnessAndContrastOfKnownImages) {
  cv::Mat half(10, 10, CV_8UC1, cv::Scalar(0));
  half.colRange(5, 10).setTo(200);
  const ImageStatistics s = imageStatistics(half);
  EXPECT_NEAR(s.brightness, 100.0, 1e-9);
  EXPECT_NEAR(s.contrast, 100.0, 1e-9);
  EXPECT_TRUE(isUsable(s, {}));
  EXPECT_FALSE(isUsable(imageStatistics(cv::Mat(10, 10, CV_8UC1, cv::Scalar(255))), {}));
  EXPECT_FALSE(isUsable(imageStatistics(cv::Mat(10, 10, CV_8UC1, cv::Scalar(120))), {}));
}

}  // namespace
}  // namespace lvslam::visual
