#include "lvslam/system/frame_stats_stream.h"

#include <cmath>

#include "lvslam/core/error.h"

namespace lvslam::system {

namespace {

const char* sourceName(OutputSource s) { return s == OutputSource::kVisual ? "visual" : "lidar"; }

}  // namespace

eval::JsonObject onlineFrameJson(const FrameOutput& f, bool timings) {
  eval::JsonObject o;
  o.addNumber("t", f.t).addString("source", sourceName(f.source)).addRaw("pose", f.T_world_camera ? "true" : "false");
  if (!f.problem.empty()) o.addString("problem", f.problem);
  if (f.fused) o.addRaw("fused_with_lidar", "true");
  if (f.visual_chi_square_per_dof >= 0.0) o.addNumber("visual_chi2_per_dof", f.visual_chi_square_per_dof);
  if (f.lidar_noise_scale != 1.0) o.addNumber("lidar_noise_scale", f.lidar_noise_scale);
  if (f.visual_noise_scale != 1.0) o.addNumber("visual_noise_scale", f.visual_noise_scale);
  if (f.covariance) {  // the estimator's own uncertainty of this pose (window solved, older frames held)
    o.addNumber("position_sigma_m", std::sqrt(f.covariance->topLeftCorner<3, 3>().trace()));
    o.addNumber("rotation_sigma_deg", std::sqrt(f.covariance->bottomRightCorner<3, 3>().trace()) * 180.0 / M_PI);
  }
  if (!f.gated.empty()) {
    std::string gated = "[";
    for (std::size_t i = 0; i < f.gated.size(); ++i) {
      const GateEvent& g = f.gated[i];
      gated += (i ? ", " : "") + eval::JsonObject()
                                     .addString("factor", factorSourceName(g.source))
                                     .addNumber("chi2", g.chi_square)
                                     .addNumber("threshold", g.threshold)
                                     .addString("reason", g.reason)
                                     .str();
    }
    o.addRaw("gated", gated + "]");
  }
  if (timings) o.addNumber("latency_ms", f.latency_ms);
  return o;
}

FrameStatsStream::FrameStatsStream(const std::string& path, bool timings)
    : path_(path), out_(path), timings_(timings) {
  if (!out_) throw Error(path, "cannot write file");
}

void FrameStatsStream::add(const FrameOutput& frame) {
  out_ << onlineFrameJson(frame, timings_).str() << '\n' << std::flush;
  if (!out_) throw Error(path_, "write failed");
}

}  // namespace lvslam::system
