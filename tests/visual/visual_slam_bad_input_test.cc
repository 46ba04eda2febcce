// VisualSlam on bad images in the rendered room sequence: saturated,
// featureless and blurred frames and a jump. Tracking says lost (no pose,
// never a wrong one), the map is kept while the images are unusable, and
// tracking comes back when they are usable again: relocalised into the old
// map, or in a new map initialised metrically from the depth hints.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "lvslam/eval/evaluate.h"
#include "lvslam/visual/visual_slam.h"
#include "visual/rendered_room.h"

namespace lvslam::visual {
namespace {

// Turns a rendered frame's image into a bad one.
using Spoil = std::function<cv::Mat(const cv::Mat&)>;

cv::Mat black(const cv::Mat& image) { return cv::Mat(image.size(), CV_8UC1, cv::Scalar(0)); }
cv::Mat saturated(const cv::Mat& image) { return cv::Mat(image.size(), CV_8UC1, cv::Scalar(255)); }
cv::Mat uniformGrey(const cv::Mat& image) { return cv::Mat(image.size(), CV_8UC1, cv::Scalar(128)); }

// 0 at the left edge to 255 at the right: contrast without a corner.
cv::Mat horizontalGradient(const cv::Mat& image) {
  cv::Mat gradient(image.size(), CV_8UC1);
  for (int u = 0; u < gradient.cols; ++u) gradient.col(u).setTo(255 * u / (gradient.cols - 1));
  return gradient;
}

Spoil blurred(double sigma_px) {
  return [sigma_px](const cv::Mat& image) {
    cv::Mat out;
    cv::GaussianBlur(image, out, cv::Size(), sigma_px);
    return out;
  };
}

// The same keyframe poses and landmark positions, none added or removed.
void expectSameMap(const VisualMap& now, const VisualMap& kept) {
  ASSERT_EQ(now.keyframes().size(), kept.keyframes().size());
  ASSERT_EQ(now.points().size(), kept.points().size());
  ASSERT_EQ(now.lines().size(), kept.lines().size());
  for (const auto& [id, k] : kept.keyframes()) {
    ASSERT_TRUE(now.hasKeyframe(id));
    EXPECT_TRUE(now.keyframe(id).T_camera_world.matrix() == k.T_camera_world.matrix()) << "keyframe " << id;
  }
  for (const auto& [id, p] : kept.points()) {
    ASSERT_TRUE(now.points().count(id));
    EXPECT_TRUE(now.point(id).p_world == p.p_world) << "point " << id;
  }
  for (const auto& [id, l] : kept.lines()) {
    ASSERT_TRUE(now.lines().count(id));
    EXPECT_TRUE(now.line(id).start_world == l.start_world && now.line(id).end_world == l.end_world) << "line " << id;
  }
}

Trajectory joined(Trajectory a, const Trajectory& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

class VisualSlamBadInputTest : public testing::RenderedRoomTest {
 protected:
  // Tracking runs from frame ~20 (monocular initialisation waits for parallax).
  static constexpr size_t kBadBegin = 30, kBadEnd = 35;
  // 22 frames (1.47 s) skipped: the camera moves ~0.6 m and turns ~24 deg.
  static constexpr size_t kJumpFrom = 24, kJumpTo = 46;

  // The sequence in three parts: frames [0, begin) as rendered, [begin, end)
  // spoilt (at their own times: the camera keeps moving), [end, size) as rendered.
  struct SpoiltRun {
    Trajectory before, before_truth;
    VisualMap map_before;  // after the last frame before the spoilt ones
    std::vector<VisualFrameResult> spoilt;
    std::vector<VisualMap> map_during;  // after each spoilt frame
    Trajectory spoilt_estimate, spoilt_truth;  // poses reported for spoilt frames
    std::vector<VisualFrameResult> after;
    Trajectory after_estimate, after_truth;
    std::vector<VisualMap> retired;  // the maps given up, at the end
  };

  static SpoiltRun runSpoilt(const VisualSlamConfig& config, const Spoil& spoil, size_t begin = kBadBegin,
                             size_t end = kBadEnd) {
    VisualSlam slam(config, camera());
    SpoiltRun out;
    run(slam, 0, begin, out.before, out.before_truth);
    EXPECT_EQ(slam.state(), TrackingState::kTracking);
    out.map_before = slam.map();
    for (size_t i = begin; i < end; ++i) {
      const RenderedFrame& f = (*frames_)[i];
      if (slam.needsDepthHints()) slam.setDepthHints(depthHints(f.depth));
      const VisualFrameResult r = slam.track(ImageFrame{f.image.timestamp, spoil(f.image.image)});
      out.spoilt.push_back(r);
      out.map_during.push_back(slam.map());
      if (!r.pose_valid) continue;
      out.spoilt_estimate.push_back({r.timestamp, r.T_world_camera});
      out.spoilt_truth.push_back({r.timestamp, f.T_world_camera});
    }
    run(slam, end, frames_->size(), out.after_estimate, out.after_truth, &out.after);
    out.retired = slam.retiredMaps();
    return out;
  }

  // Every spoilt frame: lost, no pose, the map untouched.
  static void expectLostAndMapKept(const SpoiltRun& r) {
    for (size_t k = 0; k < r.spoilt.size(); ++k) {
      SCOPED_TRACE("spoilt frame " + std::to_string(k));
      EXPECT_EQ(r.spoilt[k].state, TrackingState::kLost);
      EXPECT_FALSE(r.spoilt[k].pose_valid);
      EXPECT_EQ(r.spoilt[k].map_id, 0);
      expectSameMap(r.map_during[k], r.map_before);
    }
  }

  // Every good frame after the spoilt ones has a pose in map 0 (relocalised
  // or still tracked): one world frame, so one SE3 alignment fits before and after.
  static void expectPosesInTheOldMap(const SpoiltRun& r) {
    ASSERT_FALSE(r.after.empty());
    for (const VisualFrameResult& result : r.after) {
      EXPECT_TRUE(result.pose_valid);
      EXPECT_EQ(result.map_id, 0);
      EXPECT_EQ(result.state, TrackingState::kTracking);
    }
    ASSERT_FALSE(r.before.empty());
    ASSERT_FALSE(r.after_estimate.empty());
    const eval::EvalResult accuracy =
        se3Accuracy(joined(r.before_truth, r.after_truth), joined(r.before, r.after_estimate));
    EXPECT_LT(accuracy.ate.stats.rmse, 0.05);
    EXPECT_LT(accuracy.ate.stats.max, 0.1);
    // The first pose after the spoilt frames against the last one before them,
    // no alignment: a wrong relocalisation shows here whatever follows it.
    const Eigen::Isometry3d moved = r.before.back().T_world_frame.inverse() * r.after_estimate.front().T_world_frame;
    const Eigen::Isometry3d moved_truth =
        r.before_truth.back().T_world_frame.inverse() * r.after_truth.front().T_world_frame;
    EXPECT_LT((moved.translation() - moved_truth.translation()).norm(), 0.03);
  }

  // Tracking ends in map `map_id`, initialised metrically; its poses fit the
  // truth under their own SE3 alignment (another world frame than map 0's).
  static void expectNewMetricMap(const std::vector<VisualFrameResult>& results, const Trajectory& estimate,
                                 const Trajectory& truth, int map_id) {
    const auto first = std::find_if(results.begin(), results.end(), [](const auto& r) { return r.pose_valid; });
    ASSERT_NE(first, results.end());
    for (auto it = first; it != results.end(); ++it) {
      EXPECT_TRUE(it->pose_valid);  // from the initialisation on, every frame
      EXPECT_EQ(it->map_id, map_id);
      EXPECT_TRUE(it->metric);
      EXPECT_EQ(it->state, TrackingState::kTracking);
    }
    ASSERT_GE(estimate.size(), 5u);
    const eval::EvalResult accuracy = se3Accuracy(truth, estimate);
    EXPECT_LT(accuracy.ate.stats.rmse, 0.05);
  }
};

// Within config.relocalize_frames (15) the first good frame after five
// saturated ones is relocalised into the old map.
TEST_F(VisualSlamBadInputTest, SaturatedFramesAreLostThenRelocalisedIntoTheOldMap) {
  const VisualSlamConfig config;
  const SpoiltRun r = runSpoilt(config, saturated);
  expectLostAndMapKept(r);
  for (const VisualFrameResult& result : r.spoilt) EXPECT_GT(result.health.brightness, config.usability.max_brightness);
  expectPosesInTheOldMap(r);
}

// Lost for longer than config.relocalize_frames: the first good frame starts
// map 1 metrically from its depth hints.
TEST_F(VisualSlamBadInputTest, SaturatedFramesPastTheRelocalisationWindowStartANewMetricMap) {
  VisualSlamConfig config;
  config.relocalize_frames = 2;
  const SpoiltRun r = runSpoilt(config, saturated);
  expectLostAndMapKept(r);
  for (const VisualFrameResult& result : r.spoilt) EXPECT_GT(result.health.brightness, config.usability.max_brightness);
  ASSERT_FALSE(r.after.empty());
  // The old map is given up at once; the frame's depths start the new one.
  EXPECT_EQ(r.after.front().state, TrackingState::kTracking);
  EXPECT_TRUE(r.after.front().pose_valid);
  EXPECT_EQ(r.after.front().map_id, 1);
  expectNewMetricMap(r.after, r.after_estimate, r.after_truth, 1);
}

// Uniform grey fails the contrast test; the gradient passes it and is
// refused for its keypoints alone.
TEST_F(VisualSlamBadInputTest, FeaturelessFramesAreLostThenRelocalisedIntoTheOldMap) {
  const VisualSlamConfig config;
  for (const auto& [name, spoil, enough_contrast] : {std::tuple{"uniform grey", Spoil(uniformGrey), false},
                                                     std::tuple{"gradient", Spoil(horizontalGradient), true}}) {
    SCOPED_TRACE(name);
    const SpoiltRun r = runSpoilt(config, spoil);
    expectLostAndMapKept(r);
    for (const VisualFrameResult& result : r.spoilt) {
      EXPECT_LT(result.health.keypoints, config.min_keypoints);
      EXPECT_EQ(result.health.contrast >= config.usability.min_contrast, enough_contrast);
    }
    expectPosesInTheOldMap(r);
  }
}

// Blur keeps brightness and contrast; what it takes away decides. At 3 and
// 5 px the coarser pyramid levels keep keypoints that match the map within
// ORB-SLAM's TH_HIGH, so the frames are tracked; at 15 px no keypoint is
// left and they are lost. No blurred frame gets a pose its own stated
// uncertainty does not cover: each is within three sigmas of the truth at
// the pixel noise the online estimator assumes for the tracker
// (FusedEstimatorConfig::visual_pixel_sigma), and at 3 px within 5 cm. The
// first sharp frame has a pose in map 0 in all three.
TEST_F(VisualSlamBadInputTest, BlurredFramesAreTrackedWithinTheirStatedUncertaintyOrLost) {
  constexpr double kEstimatorPixelSigma = 3.0;
  const VisualSlamConfig config;
  struct Case {
    double sigma_px;
    bool tracked, enough_keypoints;
  };
  for (const Case c : {Case{3.0, true, true}, Case{5.0, true, true}, Case{15.0, false, false}}) {
    SCOPED_TRACE("sigma " + std::to_string(c.sigma_px) + " px");
    const SpoiltRun r = runSpoilt(config, blurred(c.sigma_px));
    for (const VisualFrameResult& result : r.spoilt) {
      EXPECT_EQ(result.pose_valid, c.tracked);
      EXPECT_EQ(result.state, c.tracked ? TrackingState::kTracking : TrackingState::kLost);
      EXPECT_EQ(result.map_id, 0);
      EXPECT_EQ(result.health.keypoints >= config.min_keypoints, c.enough_keypoints);
      EXPECT_GE(result.health.contrast, config.usability.min_contrast);
      if (!c.tracked) {
        EXPECT_LT(result.health.tracked_points, config.min_tracked);
      }
    }
    if (!c.tracked) expectLostAndMapKept(r);
    // The blurred frames' poses against the truth under the sharp frames' alignment.
    const eval::EvalResult sharp =
        se3Accuracy(joined(r.before_truth, r.after_truth), joined(r.before, r.after_estimate));
    ASSERT_EQ(r.spoilt_estimate.size(), c.tracked ? r.spoilt.size() : 0u);
    for (std::size_t k = 0; k < r.spoilt_estimate.size(); ++k) {
      SCOPED_TRACE("blurred frame " + std::to_string(k));
      ASSERT_TRUE(r.spoilt[k].fusion.pose_information.has_value());
      const Eigen::Matrix3d position_covariance = r.spoilt[k].fusion.pose_information->inverse().topLeftCorner<3, 3>() *
                                                  (kEstimatorPixelSigma * kEstimatorPixelSigma);
      const double error = (sharp.ate.T_gt_est.apply(r.spoilt_estimate[k].T_world_frame.translation()) -
                            r.spoilt_truth[k].T_world_frame.translation())
                               .norm();
      EXPECT_LT(error, 3.0 * std::sqrt(position_covariance.trace()));
      if (c.sigma_px <= 3.0) {
        EXPECT_LT(error, 0.05);
      }
    }
    expectPosesInTheOldMap(r);
  }
}

// Relocalisation searches around the last pose (relocalizationGuesses), so
// after the jump no frame of the old map's 15-frame window gets a pose: all
// stay lost rather than take a wrong one, and the map is kept.
TEST_F(VisualSlamBadInputTest, AJumpIsLostNotRelocalisedToAWrongPose) {
  VisualSlam slam(VisualSlamConfig{}, camera());
  Trajectory before, before_truth;
  run(slam, 0, kJumpFrom, before, before_truth);
  ASSERT_EQ(slam.state(), TrackingState::kTracking);
  const VisualMap kept = slam.map();
  std::vector<VisualFrameResult> results;
  Trajectory after, after_truth;
  run(slam, kJumpTo, frames_->size(), after, after_truth, &results);
  ASSERT_LE(results.size(), static_cast<size_t>(VisualSlamConfig{}.relocalize_frames));
  for (const VisualFrameResult& r : results) {
    EXPECT_EQ(r.state, TrackingState::kLost);
    EXPECT_FALSE(r.pose_valid);
    EXPECT_EQ(r.map_id, 0);
  }
  expectSameMap(slam.map(), kept);
}

// The same jump with a short relocalisation window: map 0 never gets a pose
// after the jump, map 1 starts and initialises metrically.
TEST_F(VisualSlamBadInputTest, AJumpPastTheRelocalisationWindowStartsANewMetricMap) {
  VisualSlamConfig config;
  config.relocalize_frames = 2;
  VisualSlam slam(config, camera());
  Trajectory before, before_truth;
  run(slam, 0, kJumpFrom, before, before_truth);
  ASSERT_EQ(slam.state(), TrackingState::kTracking);
  std::vector<VisualFrameResult> results;
  Trajectory after, after_truth;
  run(slam, kJumpTo, frames_->size(), after, after_truth, &results);
  for (const VisualFrameResult& r : results) {
    if (r.map_id == 0) {
      EXPECT_FALSE(r.pose_valid);
    }
  }
  expectNewMetricMap(results, after, after_truth, 1);
}

// Frames missing from the recording (dropped, not spoilt): the next one comes
// several frame intervals later, and the motion model carries the camera
// over all of them, so tracking goes on in the same map.
TEST_F(VisualSlamBadInputTest, DroppedFramesAreBridgedByTheMotionModel) {
  for (const size_t dropped : {3u, 6u}) {
    SCOPED_TRACE(std::to_string(dropped) + " frames dropped");
    VisualSlam slam(VisualSlamConfig{}, camera());
    Trajectory before, before_truth;
    run(slam, 0, kBadBegin, before, before_truth);
    ASSERT_EQ(slam.state(), TrackingState::kTracking);
    std::vector<VisualFrameResult> after;
    Trajectory after_estimate, after_truth;
    run(slam, kBadBegin + dropped, frames_->size(), after_estimate, after_truth, &after);
    ASSERT_FALSE(after.empty());
    for (const VisualFrameResult& r : after) {
      EXPECT_TRUE(r.pose_valid);
      EXPECT_EQ(r.map_id, 0);
    }
    const eval::EvalResult accuracy =
        se3Accuracy(joined(before_truth, after_truth), joined(before, after_estimate));
    EXPECT_LT(accuracy.ate.stats.rmse, 0.05);
    EXPECT_LT(accuracy.ate.stats.max, 0.1);
  }
}

// Ten unusable frames of every kind, far past config.relocalize_frames: the
// map stays as it was, since there is nothing to relocalise with; the first
// usable frame starts map 1, and map 0 is kept as it was.
TEST_F(VisualSlamBadInputTest, TheMapIsKeptWhileFramesAreUnusable) {
  VisualSlamConfig config;
  config.relocalize_frames = 2;
  const std::vector<Spoil> kinds = {black, saturated, uniformGrey, horizontalGradient, blurred(15.0)};
  const Spoil each_kind = [&kinds, k = size_t{0}](const cv::Mat& image) mutable {  // the kinds in turn
    return kinds[k++ % kinds.size()](image);
  };
  const SpoiltRun r = runSpoilt(config, each_kind, kBadBegin, kBadBegin + 10);
  ASSERT_EQ(r.spoilt.size(), 10u);
  EXPECT_GT(r.map_before.keyframes().size(), 2u);
  EXPECT_GT(r.map_before.points().size(), 100u);
  expectLostAndMapKept(r);
  expectNewMetricMap(r.after, r.after_estimate, r.after_truth, 1);
  ASSERT_EQ(r.retired.size(), 1u);
  expectSameMap(r.retired[0], r.map_before);
}

}  // namespace
}  // namespace lvslam::visual
