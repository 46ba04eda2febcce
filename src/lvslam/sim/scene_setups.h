#pragma once
// The three M2DGR-like scenes. Each adds its geometry to the builder and
// says how the robot drives and how the scene is lit.
#include "lvslam/sim/scenario.h"
#include "lvslam/sim/scene_builder.h"

namespace lvslam::sim {

struct SceneSetup {
  PathConfig path;
  Lighting day, night;
  double exposure = 0.012;     // seconds
  bool blur_by_default = false;
  WalkingPerson person;        // used when the options ask for one
};

// Texture-rich office about 10 x 8 x 3 m: desks, shelves, boxes, doors,
// windows, posters; slow motion (0.4 m/s).
SceneSetup buildRoomScene(SceneBuilder& scene);
// Hall about 30 x 20 x 6 m with a row of pillars, ceiling beams and regular
// windows; 1 m/s with motion blur.
SceneSetup buildHallScene(SceneBuilder& scene);
// Outdoors: facades with windows, a gate in a fence, trees, lamp posts,
// kerbs, long ranges and open sky.
SceneSetup buildGateScene(SceneBuilder& scene);

}  // namespace lvslam::sim
