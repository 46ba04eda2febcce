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

struct SimOptions {
  std::string scenario = "room";  // room | hall | gate
  double duration = 60.0;         // seconds
  std::uint64_t seed = 1;
  bool night = false;
  std::optional<bool> blur;       // motion blur; the scenario decides when unset (on for hall)
  bool distortion = false;        // radtan lens distortion, rendered and written
  bool walking_person = false;    // a person (moving box) walks through the scene
  std::optional<ExtrinsicError> extrinsic_error;
  std::optional<TimeInterval> camera_blackout;
  double start_time = 1700000000.0;  // Unix-like epoch of the sequence start
};

// Throws lvslam::Error("--scenario" / "--duration" / ..., why).
void validate(const SimOptions& options);

// "DEG,M" -> ExtrinsicError; "T0,T1" -> TimeInterval; Error names the option.
ExtrinsicError parseExtrinsicError(const std::string& text);
TimeInterval parseTimeInterval(const std::string& text, const std::string& option);

}  // namespace lvslam::sim
