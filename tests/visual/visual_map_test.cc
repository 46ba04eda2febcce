#include "lvslam/visual/data/visual_map.h"

#include <gtest/gtest.h>

#include <optional>
#include <vector>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"

namespace lvslam::visual {
namespace {

Keyframe keyframeWith(int num_points, int num_lines) {
  Keyframe kf;
  kf.features.keypoints.resize(num_points);
  kf.features.lines.resize(num_lines);
  return kf;
}

TEST(CovisibilityGraph, WeightsAreSymmetricAndSortedHeaviestFirst) {
  CovisibilityGraph g;
  g.addWeight(0, 1, 5);
  g.addWeight(0, 2, 9);
  g.addWeight(3, 0, 5);
  EXPECT_EQ(g.weight(1, 0), 5);
  EXPECT_EQ(g.neighbours(0), (std::vector<int>{2, 1, 3}));
  EXPECT_EQ(g.neighbours(0, 6), (std::vector<int>{2}));
  EXPECT_EQ(g.bestNeighbours(0, 2), (std::vector<int>{2, 1}));
  g.addWeight(0, 2, -9);
  EXPECT_EQ(g.weight(0, 2), 0);
  EXPECT_EQ(g.neighbours(2), std::vector<int>{});
  g.removeNode(0);
  EXPECT_EQ(g.weight(1, 0), 0);
  EXPECT_TRUE(g.neighbours(3).empty());
}

TEST(VisualMap, ObservationsBuildTheCovisibilityGraph) {
  VisualMap map;
  const int a = map.addKeyframe(keyframeWith(10, 3));
  const int b = map.addKeyframe(keyframeWith(10, 3));
  const int c = map.addKeyframe(keyframeWith(10, 3));
  EXPECT_EQ(map.keyframe(a).point_landmark.size(), 10u);
  std::vector<int> points;
  for (int i = 0; i < 4; ++i) points.push_back(map.addPointLandmark(Eigen::Vector3d(i, 0, 5), cv::Mat()));
  const int line = map.addLineLandmark(PluckerLine::fromPoints({0, 0, 5}, {1, 0, 5}), {0, 0, 5}, {1, 0, 5}, cv::Mat());
  // a and b share 4 points and a line; b and c share 1 point.
  for (int i = 0; i < 4; ++i) {
    map.addPointObservation(points[i], a, i);
    map.addPointObservation(points[i], b, i + 2);
  }
  map.addPointObservation(points[0], c, 7);
  map.addLineObservation(line, a, 0);
  map.addLineObservation(line, b, 2);
  EXPECT_EQ(map.covisibility().weight(a, b), 5);
  EXPECT_EQ(map.covisibility().weight(b, c), 1);
  EXPECT_EQ(map.covisibility().weight(a, c), 1);
  EXPECT_EQ(map.keyframe(b).point_landmark[3], points[1]);
  EXPECT_EQ(map.keyframe(b).line_landmark[2], line);
  EXPECT_EQ(map.localWindow(a, 2), (std::vector<int>{a, b}));
  EXPECT_EQ(map.localWindow(b, 5), (std::vector<int>{b, a, c}));

  map.removePointObservation(points[0], c);
  EXPECT_EQ(map.covisibility().weight(b, c), 0);
  EXPECT_EQ(map.keyframe(c).point_landmark[7], -1);
  map.removeLine(line);
  EXPECT_FALSE(map.hasLine(line));
  EXPECT_THROW(map.line(line), Error);
  EXPECT_EQ(map.keyframe(a).line_landmark[0], -1);
  EXPECT_EQ(map.covisibility().weight(a, b), 4);
}

TEST(VisualMap, FusionDirectionIsStoredUnitAndFlagged) {
  VisualMap map;
  const int l = map.addLineLandmark(PluckerLine::fromPoints({0, 0, 5}, {1, 0, 5}), {0, 0, 5}, {1, 0, 5}, cv::Mat());
  EXPECT_FALSE(map.line(l).fusion_direction.has_value());
  EXPECT_FALSE(map.line(l).from_fusion);
  map.setFusionDirection(l, Eigen::Vector3d(2, 0, 0));
  EXPECT_TRUE(map.line(l).fusion_direction->isApprox(Eigen::Vector3d::UnitX()));
  EXPECT_THROW(map.setFusionDirection(l, Eigen::Vector3d::Zero()), Error);
}

// The first odometry pose aligns the odometry's world with the map; later
// ones come back as priors moved into the map through that alignment.
TEST(VisualMap, OdometryPosesBecomePriorsInTheMapFrame) {
  VisualMap map;
  Keyframe k0, k1;
  Vector6d xi0, xi1, xi_odom;
  xi0 << 0.1, -0.2, 0.3, 0.05, -0.1, 0.2;
  xi1 << 0.6, -0.1, 0.2, 0.1, 0.3, -0.2;
  xi_odom << 5.0, -3.0, 1.0, 0.0, 0.0, 1.2;  // the odometry's world: elsewhere, turned
  k0.T_camera_world = expSE3(xi0);
  k1.T_camera_world = expSE3(xi1);
  const int a = map.addKeyframe(k0), b = map.addKeyframe(k1);
  const Eigen::Isometry3d T_odom_world = expSE3(xi_odom);
  EXPECT_FALSE(map.odometryPrior(a).has_value());
  map.setOdometryPose(a, T_odom_world * k0.T_camera_world.inverse());
  ASSERT_TRUE(map.T_world_odom().has_value());
  EXPECT_TRUE(map.T_world_odom()->isApprox(T_odom_world.inverse(), 1e-12));
  EXPECT_TRUE(map.odometryPrior(a)->isApprox(k0.T_camera_world, 1e-12));
  EXPECT_FALSE(map.odometryPrior(b).has_value());
  // The odometry sees keyframe b 2 cm off: the prior is that pose in the map.
  const Eigen::Isometry3d off(Eigen::Translation3d(0.02, 0.0, 0.0));
  map.setOdometryPose(b, T_odom_world * off * k1.T_camera_world.inverse());
  EXPECT_TRUE(map.odometryPrior(b)->isApprox((off * k1.T_camera_world.inverse()).inverse(), 1e-12));
  Eigen::Isometry3d bad = Eigen::Isometry3d::Identity();
  bad.linear() *= 2.0;
  EXPECT_THROW(map.setOdometryPose(b, bad), Error);
  EXPECT_THROW(map.setOdometryPose(99, Eigen::Isometry3d::Identity()), Error);
}

// Landmarks are looked up by id through an index into the map's own nodes:
// a copy must find its own landmarks, and a moved map keeps finding them.
TEST(VisualMap, CopiesAndMovesLookUpTheirOwnLandmarks) {
  VisualMap original;
  const int kf = original.addKeyframe(keyframeWith(4, 2));
  const int p = original.addPointLandmark(Eigen::Vector3d(1, 2, 3), cv::Mat());
  const int l = original.addLineLandmark(PluckerLine::fromPoints(Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1)),
                                         Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1), cv::Mat());
  original.addPointObservation(p, kf, 0);

  VisualMap copy = original;
  copy.point(p).p_world.x() = 10.0;
  copy.removeLine(l);
  EXPECT_EQ(&copy.point(p), &copy.points().at(p));
  EXPECT_DOUBLE_EQ(original.point(p).p_world.x(), 1.0);
  EXPECT_TRUE(original.hasLine(l));
  EXPECT_FALSE(copy.hasLine(l));
  // The copy's next id follows every id ever assigned, the removed line's too.
  EXPECT_EQ(copy.addLineLandmark(original.line(l).line_world, Eigen::Vector3d(0, 0, 1), Eigen::Vector3d(1, 0, 1), cv::Mat()),
            l + 1);

  VisualMap assigned;
  assigned = copy;
  EXPECT_EQ(&assigned.point(p), &assigned.points().at(p));
  EXPECT_DOUBLE_EQ(assigned.point(p).p_world.x(), 10.0);

  const VisualMap moved = std::move(copy);
  EXPECT_EQ(&moved.point(p), &moved.points().at(p));
  EXPECT_DOUBLE_EQ(moved.point(p).p_world.x(), 10.0);
  EXPECT_THROW(moved.point(p + 1), Error);
  EXPECT_THROW(moved.line(-1), Error);
}

// ORB-SLAM's distinctive descriptor: of the keyframes' views of a point, the
// one whose median Hamming distance to the others is least. The creating
// view has 40 bits of its own; the central view none; three more views
// three bits each, apart from each other. With two views neither is more
// central and the point keeps its descriptor.
TEST(VisualMap, APointTakesItsMostCentralViewsDescriptor) {
  const auto descriptorWith = [](int first_bit, int bits) {
    cv::Mat d(1, 32, CV_8U, cv::Scalar(0));
    for (int bit = first_bit; bit < first_bit + bits; ++bit) d.at<uint8_t>(0, bit / 8) |= static_cast<uint8_t>(1u << (bit % 8));
    return d;
  };
  const cv::Mat creating = descriptorWith(100, 40), central = descriptorWith(0, 0);
  const std::vector<cv::Mat> views{creating, descriptorWith(0, 3), central, descriptorWith(3, 3), descriptorWith(6, 3)};
  const auto distance = [](const cv::Mat& a, const cv::Mat& b) { return cv::norm(a, b, cv::NORM_HAMMING); };
  VisualMap map;
  const int p = map.addPointLandmark(Eigen::Vector3d(0, 0, 5), creating);
  std::optional<VisualMap> copy;
  for (const cv::Mat& view : views) {
    Keyframe kf = keyframeWith(2, 0);
    kf.features.descriptors = cv::Mat(2, 32, CV_8U, cv::Scalar(255));
    view.copyTo(kf.features.descriptors.row(1));
    map.addPointObservation(p, map.addKeyframe(std::move(kf)), 1);
    if (map.point(p).observations.size() == 2) {
      EXPECT_EQ(distance(map.point(p).descriptor, creating), 0.0);
      copy = map;
    }
  }
  EXPECT_EQ(distance(map.point(p).descriptor, central), 0.0);
  // A copy of the map keeps its own descriptor when the original's changes.
  EXPECT_EQ(distance(copy->point(p).descriptor, creating), 0.0);
}

// The time a pose's landmarks were mapped: the median of their first
// observers' times, whoever observed them later; bad and absent ones skipped.
TEST(VisualMap, MedianFirstSeenTakesEachLandmarksFirstObserver) {
  VisualMap map;
  std::vector<int> kf;
  for (int i = 0; i < 4; ++i) {
    Keyframe k = keyframeWith(4, 0);
    k.timestamp = 10.0 * i;
    kf.push_back(map.addKeyframe(k));
  }
  std::vector<int> points;
  for (int i = 0; i < 4; ++i) {
    points.push_back(map.addPointLandmark(Eigen::Vector3d(i, 0, 5), cv::Mat()));
    map.addPointObservation(points[i], kf[i], i);                // first seen by keyframe i (t = 10 i)
    if (i < 3) map.addPointObservation(points[i], kf[3], i);     // all seen again by the newest
  }
  EXPECT_FALSE(medianFirstSeen(map, {}).has_value());
  EXPECT_FALSE(medianFirstSeen(map, {-1, -1}).has_value());
  EXPECT_DOUBLE_EQ(*medianFirstSeen(map, {points[0], -1, points[1], points[2]}), 10.0);
  map.removePoint(points[0]);
  EXPECT_DOUBLE_EQ(*medianFirstSeen(map, {points[0], points[1], points[2], points[3]}), 20.0);
}

// A removed keyframe keeps its pose relative to its most covisible keyframe
// (else the nearest older one) and follows it when it moves; chains of
// removals resolve through each parent in turn.
TEST(VisualMap, RemovedKeyframesFollowTheirParents) {
  VisualMap map;
  std::vector<int> ids;
  for (int i = 0; i < 4; ++i) {
    Keyframe kf = keyframeWith(4, 0);
    kf.T_camera_world = expSE3((Vector6d() << 0.1 * i, -0.05 * i, 0.3 * i, 0.01 * i, 0.02, -0.03 * i).finished());
    ids.push_back(map.addKeyframe(std::move(kf)));
  }
  // ids[2] shares two points with ids[3] and one with ids[1]: its parent is ids[3].
  for (int i = 0; i < 2; ++i) {
    const int p = map.addPointLandmark(Eigen::Vector3d(i, 1, 5), cv::Mat());
    map.addPointObservation(p, ids[2], i);
    map.addPointObservation(p, ids[3], i);
  }
  const int shared = map.addPointLandmark(Eigen::Vector3d(0, 2, 5), cv::Mat());
  map.addPointObservation(shared, ids[2], 2);
  map.addPointObservation(shared, ids[1], 2);
  const Eigen::Isometry3d T2 = map.keyframe(ids[2]).T_camera_world, T3 = map.keyframe(ids[3]).T_camera_world;
  const Eigen::Isometry3d T1 = map.keyframe(ids[1]).T_camera_world;
  map.removeKeyframe(ids[2]);
  EXPECT_FALSE(map.hasKeyframe(ids[2]));
  ASSERT_TRUE(map.keyframePose(ids[2]).has_value());
  EXPECT_TRUE(map.keyframePose(ids[2])->isApprox(T2, 1e-12));
  // BA moves the parent: the removed keyframe moves with it, rigidly.
  const Eigen::Isometry3d move = expSE3((Vector6d() << 0.2, 0.0, -0.1, 0.0, 0.05, 0.0).finished());
  map.keyframe(ids[3]).T_camera_world = T3 * move;
  EXPECT_TRUE(map.keyframePose(ids[2])->isApprox(T2 * T3.inverse() * T3 * move, 1e-12));
  EXPECT_TRUE((*map.keyframePose(ids[2]) * map.keyframe(ids[3]).T_camera_world.inverse())
                  .isApprox(T2 * T3.inverse(), 1e-12));
  // ids[3] has no covisible keyframe left: its parent is the nearest older one, ids[1].
  map.removeKeyframe(ids[3]);
  const Eigen::Isometry3d T3_moved = T3 * move;
  EXPECT_TRUE(map.keyframePose(ids[3])->isApprox(T3_moved, 1e-12));
  map.keyframe(ids[1]).T_camera_world = T1 * move;
  // Through two parents: ids[2] -> ids[3] -> ids[1].
  EXPECT_TRUE(map.keyframePose(ids[2])->isApprox(T2 * T3.inverse() * T3_moved * T1.inverse() * T1 * move, 1e-9));
  EXPECT_TRUE(map.keyframePose(ids[0])->isApprox(map.keyframe(ids[0]).T_camera_world, 1e-12));
  EXPECT_FALSE(map.keyframePose(99).has_value());
  // Copies keep the removed keyframes' parents.
  const VisualMap copy = map;
  EXPECT_TRUE(copy.keyframePose(ids[2])->isApprox(*map.keyframePose(ids[2]), 1e-12));
}

TEST(VisualMap, RejectsInconsistentObservations) {
  VisualMap map;
  const int kf = map.addKeyframe(keyframeWith(2, 0));
  const int p = map.addPointLandmark(Eigen::Vector3d(0, 0, 1), cv::Mat());
  const int q = map.addPointLandmark(Eigen::Vector3d(0, 1, 1), cv::Mat());
  EXPECT_THROW(map.addPointObservation(p, kf, 2), Error);   // index out of range
  EXPECT_THROW(map.addPointObservation(p, 99, 0), Error);   // unknown keyframe
  EXPECT_THROW(map.addPointObservation(99, kf, 0), Error);  // unknown point
  EXPECT_THROW(map.addLineObservation(0, kf, 0), Error);    // no lines
  map.addPointObservation(p, kf, 0);
  EXPECT_THROW(map.addPointObservation(q, kf, 0), Error);  // feature taken
  EXPECT_THROW(map.addPointObservation(p, kf, 1), Error);  // keyframe already sees p
  EXPECT_THROW(map.addPointLandmark(Eigen::Vector3d(NAN, 0, 0), cv::Mat()), Error);
  EXPECT_THROW(map.addLineLandmark(PluckerLine{Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(1, 0, 0)}, {}, {}, cv::Mat()), Error);
  EXPECT_THROW(map.localWindow(42, 3), Error);
}

}  // namespace
}  // namespace lvslam::visual
