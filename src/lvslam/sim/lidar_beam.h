#pragma once
// One laser pulse of a spinning LiDAR: what it returns from the world and the
// walking people. A ray along the pulse's axis, or its footprint: sampled at
// 2 x 2 points across the divergence cone, echoes that overlap in time merge
// into one range between the surfaces (the "mixed pixel" at depth edges:
// Hebert and Krotkov 1992; Tang et al. 2007). Glass panes return nothing, or
// with a probability the surface behind them.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "lvslam/sim/walking_person.h"
#include "lvslam/sim/world.h"

namespace lvslam::sim {

struct BeamModel {
  double divergence = 0.003;    // radians, full angle of the footprint (VLP-32C and VLP-16: 3 mrad)
  bool footprint = false;       // sample the footprint (mixed returns); false: the central ray only
  double merge_distance = 1.5;  // metres: echoes closer than about the pulse length merge into one
  double glass_return = 0.15;   // probability that a pulse meeting glass returns from behind the pane
};

class BeamCaster {
 public:
  // The world must outlive the caster.
  BeamCaster(const World& world, const BeamModel& model) : world_(world), model_(model) {}

  // The return of the ray along `unit_dir` among the world and the people's
  // boxes at the pulse's time, or none. `glass_draw` in [0, 1) is the pulse's
  // random draw: a pane lets it return from behind when glass_draw < glass_return.
  std::optional<WorldHit> castRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& unit_dir,
                                  const std::vector<Primitive>& people, double max_range, double glass_draw) const;
  // The same pulse as a footprint (whether or not model.footprint): the hit's
  // distance is along the central ray, normal and albedo the strongest sample's.
  std::optional<WorldHit> castFootprint(const Eigen::Vector3d& origin, const Eigen::Vector3d& unit_dir,
                                        const std::vector<Primitive>& people, double max_range,
                                        double glass_draw) const;

 private:
  std::optional<WorldHit> sample(const Eigen::Vector3d& origin, const Eigen::Vector3d& unit_dir,
                                 const std::vector<Primitive>& people, double max_range, bool through_glass) const;

  const World& world_;
  BeamModel model_;
};

// Standard deviation of the range noise (metres): sigma0 + per_metre * range,
// divided by the cosine of the incidence angle floored at min_cos (a tilted
// footprint spreads the echo in time: Soudarissanane et al. 2011, "Scanning
// geometry: influencing factor on the quality of terrestrial laser scanning
// points"). min_cos 1 means no incidence effect.
double rangeSigma(double sigma0, double per_metre, double min_cos, double range, double cos_incidence);

}  // namespace lvslam::sim
