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
  std::vector<WalkingLane> lanes;  // where more people may walk (options.people > 1)
};

Lighting indoorDay();
Lighting indoorNight();
Lighting outdoorDay();
Lighting outdoorDark();  // night without street lamps

// An indoor setup lit by indoorDay (indoorNight at night), exposed `exposure`
// seconds, its person walking between two points; the caller adds the drive.
SceneSetup indoorSetup(double exposure, const Eigen::Vector2d& walk_from, const Eigen::Vector2d& walk_to);

// An outdoor setup: driven at up to 1 m/s on rougher ground, lit by
// outdoorDay (outdoorDark at night), exposed 8 ms, its person walking from-to.
SceneSetup outdoorSetup(const Eigen::Vector2d& walk_from, const Eigen::Vector2d& walk_to);

// `count` waypoints on an ellipse, each radius scaled by 1 +- `jitter` (seeded).
void addEllipseLoop(SceneBuilder& scene, PathConfig& path, const Eigen::Vector2d& centre, double rx, double ry,
                    int count, double jitter);
// The limits of a drive: speed (m/s), turn rate (rad/s), acceleration (m/s^2).
void setDrive(PathConfig& path, double max_speed, double max_turn_rate, double acceleration);

// Texture-rich office about 10 x 8 x 3 m: desks, shelves, boxes, doors,
// windows, posters; slow motion (0.4 m/s).
SceneSetup buildRoomScene(SceneBuilder& scene);
// Hall about 30 x 20 x 6 m with a row of pillars, ceiling beams and regular
// windows; 1 m/s with motion blur.
SceneSetup buildHallScene(SceneBuilder& scene);
// Outdoors: facades with windows, a gate in a fence, trees, lamp posts,
// kerbs, long ranges and open sky.
SceneSetup buildGateScene(SceneBuilder& scene);
// A 240 m corridor, 2.4 m wide: plain walls, flush doors every 6 m on both
// sides, posters; the LiDAR is degenerate along it (its ends are out of range).
SceneSetup buildCorridorScene(SceneBuilder& scene);
// An open paved yard: textured paving, few objects within LiDAR range,
// buildings beyond it.
SceneSetup buildYardScene(SceneBuilder& scene);
// An office of white walls and plain furniture: good geometry, little texture.
SceneSetup buildOfficeScene(SceneBuilder& scene);
// An atrium walled by glass: a curtain-wall facade, glass partitions in front
// of meeting rooms, pillars and a few pieces of furniture.
SceneSetup buildAtriumScene(SceneBuilder& scene);
// Two identical offices side by side along a corridor (the second a shifted
// copy of the first, furniture and textures included): a lap through one, the
// corridor, the same lap through the other. What place recognition must not
// take for a loop.
SceneSetup buildTwinsScene(SceneBuilder& scene);

}  // namespace lvslam::sim
