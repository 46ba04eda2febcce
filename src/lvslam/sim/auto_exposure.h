#pragma once
// Auto-exposure of the simulated camera: after each frame it meters the
// image's mean brightness and moves its exposure toward the one that would
// give the target, as a first-order response per frame in the log domain:
//   log f_{k+1} = log f_k + alpha (log target - log mean_k),
//   alpha = 1 - exp(-frame_period / time_constant),
// which for a linear sensor is a first-order low-pass of log f toward the
// ideal exposure (the proportional loop of consumer AE controllers). The
// factor f is spent on the shutter first, up to max_exposure (so dark scenes
// blur), then on analog gain (so they get noisier). Deterministic: it only
// depends on the images, which depend only on (seed, time).
#include <opencv2/core.hpp>

namespace lvslam::sim {

struct AutoExposureConfig {
  bool enabled = false;
  double target = 110.0;        // DN, mean brightness aimed at
  double time_constant = 0.5;   // seconds of the first-order response
  double max_exposure = 0.033;  // seconds the shutter may stay open (one 30 Hz frame)
  double min_factor = 0.1, max_factor = 16.0;  // total exposure relative to the scene's base setting
};

// What the camera is set to for one frame.
struct Exposure {
  double time = 0.012;  // seconds the shutter is open (sets the motion blur)
  double gain = 1.0;    // multiplies the scene's base gain; brightness is base_gain * gain * time / base_time
  double factor(double base_time) const { return gain * time / base_time; }
};

class AutoExposure {
 public:
  AutoExposure(const AutoExposureConfig& config, double base_exposure, double frame_period);

  Exposure current() const;
  double factor() const { return factor_; }
  // Meters a frame taken with current() and sets the next frame's exposure.
  void update(const cv::Mat& image);

 private:
  AutoExposureConfig config_;
  double base_exposure_;
  double alpha_;
  double factor_ = 1.0;
};

}  // namespace lvslam::sim
