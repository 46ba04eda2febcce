#include "lvslam/sim/families.h"

#include <algorithm>

#include "lvslam/core/error.h"

namespace lvslam::sim {

namespace {

// The realism every new family has: the LiDAR pulse as a footprint with
// range- and incidence-dependent noise, the camera's auto-exposure.
SimOptions realistic(const std::string& family, const std::string& scenario) {
  SimOptions o;
  o.family = family;
  o.scenario = scenario;
  o.beam_footprint = true;
  o.auto_exposure = true;
  return o;
}

}  // namespace

std::vector<FamilyInfo> families() {
  return {
      {"corridor", WeakerSensor::kLidar, "240 m corridor, plain walls, flush doors: LiDAR degenerate along the axis"},
      {"hall16", WeakerSensor::kLidar, "the hall with a 16-ring LiDAR at 1.6x the speed: sparse vertical coverage"},
      {"glass", WeakerSensor::kLidar, "atrium walled by glass: no LiDAR returns from most walls"},
      {"yard", WeakerSensor::kLidar, "open paved yard: little within LiDAR range besides the ground"},
      {"crowd", WeakerSensor::kLidar, "the hall with 12 people walking: moving returns at LiDAR height"},
      {"dropout", WeakerSensor::kLidar, "the room with the LiDAR silent for 2 s (from 10 s)"},
      {"night", WeakerSensor::kCamera, "the gate at night: dark, noisy, long-exposure images"},
      {"blur", WeakerSensor::kCamera, "the hall at 1.6x speed, 2.5x exposure, rolling shutter: blurred images"},
      {"plain", WeakerSensor::kCamera, "office of white walls and plain furniture: few corners"},
      {"blackout", WeakerSensor::kCamera, "the room with the camera dark for 6 s (from 24 s)"},
      {"room", WeakerSensor::kNeither, "the office room as `--scenario room`"},
      {"gate", WeakerSensor::kNeither, "the campus gate as `--scenario gate`"},
  };
}

std::vector<std::string> familyNames() {
  std::vector<std::string> names;
  for (const FamilyInfo& f : families()) names.push_back(f.name);
  return names;
}

SimOptions familyOptions(const std::string& name) {
  // No lens distortion in the corridor: the family's bytes as first
  // generated (docs/simulator.md; the yard is the family with distortion).
  if (name == "corridor") return realistic(name, "corridor");
  if (name == "hall16" || name == "blur") {
    SimOptions o = realistic(name, "hall");
    o.speed_scale = 1.6;
    if (name == "hall16") {
      o.lidar = "vlp16";
      o.blur = false;  // a bright hall: a 15 ms shutter or less, its blur not simulated (2 min budget)
    }
    if (name == "blur") {  // a dim hall: the shutter stays open 37.5 ms
      o.exposure_scale = 2.5;
      o.blur_samples = 4;  // 5 would overrun the generation time budget (docs/simulator.md)
      o.rolling_shutter = true;
      o.auto_exposure = false;  // the exposure is fixed (long)
    }
    return o;
  }
  if (name == "glass") return realistic(name, "atrium");
  if (name == "yard") {
    SimOptions o = realistic(name, "yard");
    o.distortion = true;
    return o;
  }
  if (name == "crowd") {
    SimOptions o = realistic(name, "hall");
    o.people = 12;
    o.blur = false;  // as hall16
    return o;
  }
  if (name == "night") {
    SimOptions o = realistic(name, "gate");
    o.night = true;
    return o;
  }
  if (name == "plain") return realistic(name, "office");
  if (name == "blackout") {
    SimOptions o = realistic(name, "room");
    o.auto_exposure = false;  // the frames are black, not dark
    o.camera_blackout = TimeInterval{24.0, 30.0};
    return o;
  }
  if (name == "dropout") {
    SimOptions o = realistic(name, "room");
    o.lidar_dropout = TimeInterval{10.0, 12.0};
    return o;
  }
  if (name == "room" || name == "gate") {
    SimOptions o;
    o.family = name;
    o.scenario = name;
    return o;
  }
  const auto names = familyNames();
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
  throw Error("--family", "unknown family '" + name + "' (expected one of " + list + ")");
}

}  // namespace lvslam::sim
