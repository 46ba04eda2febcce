#pragma once
// What `lvslam simulate` is asked for, validated with errors naming the option.
#include <cstdint>
#include <optional>
#include <string>

namespace lvslam::sim {

struct ExtrinsicError {
  double rotation_deg = 0.0;  // angle of the rotation error about a random axis
  double translation_m = 0.0; // length of the offset in a random direction
};

struct TimeInterval {
  double begin = 0.0, end = 0.0;  // seconds from the sequence start
};

// Every option's default leaves a scene byte for byte as it is without the
// option, so sequences and figures made without it stay reproducible.
struct SimOptions {
  std::string scenario = "room";  // room | hall | gate | corridor | yard | office | atrium
  std::string family;             // the family preset these options came from (families.h); names the sequence
  double duration = 60.0;         // seconds
  std::uint64_t seed = 1;
  bool night = false;
  std::optional<bool> blur;       // motion blur; the scenario decides when unset (on for hall)
  int blur_samples = 5;           // sub-exposures averaged when blurred
  bool distortion = false;        // radtan lens distortion, rendered and written
  bool walking_person = false;    // a person (moving box) walks through the scene
  int people = 0;                 // people walking on their own paths (at least 1 with walking_person)
  std::string lidar = "vlp32c";   // vlp32c (32 rings, -25..+15 deg) | vlp16 (16 rings, -15..+15 deg)
  // The LiDAR pulse as a footprint (mixed returns at depth edges) with range
  // noise growing with range and incidence, instead of an exact ray with
  // constant noise (lidar_beam.h, docs/simulator.md).
  bool beam_footprint = false;
  bool auto_exposure = false;     // exposure follows the scene's brightness with a lag (auto_exposure.h)
  bool rolling_shutter = false;   // each image row exposed at its own time
  double speed_scale = 1.0;       // multiplies the scene's speed, turn rate and acceleration
  double exposure_scale = 1.0;    // multiplies the scene's exposure time (longer: more motion blur)
  std::optional<ExtrinsicError> extrinsic_error;
  std::optional<TimeInterval> camera_blackout;
  std::optional<TimeInterval> lidar_dropout;  // no sweep that starts in it is written
  double start_time = 1700000000.0;  // Unix-like epoch of the sequence start
};

inline constexpr int kMaxPeople = 50;

// Throws lvslam::Error("--scenario" / "--duration" / ..., why).
void validate(const SimOptions& options);

// "DEG,M" -> ExtrinsicError; "T0,T1" -> TimeInterval; Error names the option.
ExtrinsicError parseExtrinsicError(const std::string& text);
TimeInterval parseTimeInterval(const std::string& text, const std::string& option);

}  // namespace lvslam::sim
