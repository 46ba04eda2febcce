#pragma once
// Families of simulated sequences: named presets of scene and options where
// one sensor is the weaker one for a physical reason (docs/simulator.md has
// the reasons and the measured single-mode errors). The bench and
// `lvslam simulate --family NAME` generate them through familyOptions.
#include <string>
#include <vector>

#include "lvslam/sim/sim_options.h"

namespace lvslam::sim {

enum class WeakerSensor { kLidar, kCamera, kNeither };

struct FamilyInfo {
  std::string name;
  WeakerSensor weaker = WeakerSensor::kNeither;
  std::string purpose;  // what it tests, one line
};

// All families, LiDAR-weaker first, then camera-weaker, then both good.
std::vector<FamilyInfo> families();
std::vector<std::string> familyNames();

// The family's options: 60 s, seed 1, `family` set (the caller may change
// duration and seed). Throws lvslam::Error("--family", ...) for an unknown name.
SimOptions familyOptions(const std::string& name);

}  // namespace lvslam::sim
