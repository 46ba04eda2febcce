#pragma once
// Pieces of outdoor scenes: building facades with framed windows, a gate in
// a fence, trees, lamp posts, kerbs and road markings.
#include "lvslam/sim/scene_builder.h"

namespace lvslam::sim {

// A building whose facade faces `wall.inward`: a brick block behind the wall
// line with a grid of framed windows and an entrance.
void addBuilding(SceneBuilder& scene, const WallFrame& wall, double depth, int floors);
// A gate (two pillars and a beam) at `xy` across the x axis of `yaw`, `opening`
// wide, and a fence of bars reaching `fence_left` / `fence_right` metres to the sides.
void addGate(SceneBuilder& scene, const Eigen::Vector2d& xy, double yaw, double opening, double fence_left,
             double fence_right);
void addTree(SceneBuilder& scene, const Eigen::Vector2d& xy);
void addLampPost(SceneBuilder& scene, const Eigen::Vector2d& xy, double height);
// A kerb box along a segment of the ground, and a painted stripe beside it.
void addKerb(SceneBuilder& scene, const Eigen::Vector2d& from, const Eigen::Vector2d& to);

}  // namespace lvslam::sim
