#include "fusion/sim_fusion_harness.h"

#include <cmath>

#include "lvslam/fusion/lidar_bridge.h"
#include "lvslam/sim/camera_renderer.h"
#include "lvslam/sim/lidar_simulator.h"
#include "lvslam/sim/scenario.h"
#include "lvslam/sim/simulate_sequence.h"

namespace lvslam::fusion::testing {

visual::LineExtractorConfig SimFusionOptions::defaultLines() {
  visual::LineExtractorConfig c;
  c.compute_descriptors = false;
  c.min_length_ratio = 30.0 / 480.0;
  return c;
}

std::vector<eval::LineMatch> SimFusionFrame::edgeMatches() const {
  std::vector<eval::LineMatch> out;
  for (const LineTruth& t : truth)
    if (t.edge) out.push_back(*t.edge);
  return out;
}

eval::AccuracySummary SimFusionRun::edgeSummary() const {
  std::vector<eval::LineMatch> all;
  for (const auto& f : frames) {
    const auto m = f.edgeMatches();
    all.insert(all.end(), m.begin(), m.end());
  }
  return eval::summarize(all);
}

double SimFusionRun::linesPerFrame() const {
  std::size_t n = 0;
  for (const auto& f : frames) n += f.output.result.lines.size();
  return frames.empty() ? 0.0 : static_cast<double>(n) / static_cast<double>(frames.size());
}

double SimFusionRun::edgeLinesPerFrame() const {
  std::size_t n = 0;
  for (const auto& f : frames) n += f.edgeMatches().size();
  return frames.empty() ? 0.0 : static_cast<double>(n) / static_cast<double>(frames.size());
}

double SimFusionRun::surfaceDistanceQuantile(double q) const {
  std::vector<double> d;
  for (const auto& f : frames)
    for (const LineTruth& t : f.truth) d.insert(d.end(), std::begin(t.surface_distance), std::end(t.surface_distance));
  return eval::quantile(d, q);
}

namespace {

constexpr double kEdgePixels = 3.0;
constexpr double kEdgeAngleDeg = 3.0;

struct Segment2 {
  Eigen::Vector2d p, q;
};

// The true edges in front of the camera, clipped to z >= 0.1 m and projected
// with the true pose (the simulator's camera has no distortion by default).
std::vector<Segment2> projectedEdges(const std::vector<eval::TrueSegment>& edges, const Eigen::Isometry3d& T_camera_world,
                                     const PinholeCamera& camera) {
  std::vector<Segment2> out;
  for (const eval::TrueSegment& e : edges) {
    Eigen::Vector3d a = T_camera_world * e.a, b = T_camera_world * e.b;
    constexpr double kNear = 0.1;
    if (a.z() < kNear && b.z() < kNear) continue;
    if (a.z() < kNear) a += (kNear - a.z()) / (b.z() - a.z()) * (b - a);
    if (b.z() < kNear) b += (kNear - b.z()) / (a.z() - b.z()) * (a - b);
    const auto pa = camera.project(a), pb = camera.project(b);
    if (pa && pb && (*pb - *pa).norm() > 1.0) out.push_back({*pa, *pb});
  }
  return out;
}

// Does a projected true edge run along the image segment?
bool runsAlong(const ImageSegment& s, const Segment2& e) {
  const Eigen::Vector2d d = (e.q - e.p).normalized();
  const Eigen::Vector2d n(-d.y(), d.x());
  if (std::abs(n.dot(s.start - e.p)) > kEdgePixels || std::abs(n.dot(s.end - e.p)) > kEdgePixels) return false;
  const Eigen::Vector2d ds = (s.end - s.start).normalized();
  if (std::abs(ds.x() * d.y() - ds.y() * d.x()) > std::sin(kEdgeAngleDeg * M_PI / 180.0)) return false;
  const double len = (e.q - e.p).norm();
  const double u0 = d.dot(s.start - e.p), u1 = d.dot(s.end - e.p);
  return std::max(u0, u1) <= len + kEdgePixels && std::min(u0, u1) >= -kEdgePixels;
}

std::vector<LineTruth> measure(const FusionResult& result, const std::vector<ImageSegment>& segments,
                               const Eigen::Isometry3d& T_world_camera, const PinholeCamera& camera,
                               const sim::World& world, const std::vector<eval::TrueSegment>& edges) {
  const std::vector<Segment2> projected = projectedEdges(edges, T_world_camera.inverse(), camera);
  std::vector<LineTruth> out;
  for (const FusionLine& line : result.lines) {
    LineTruth truth;
    const Eigen::Vector3d A = T_world_camera * line.A, B = T_world_camera * line.B;
    truth.surface_distance[0] = world.distanceToSurface(A);
    truth.surface_distance[1] = world.distanceToSurface(B);
    const ImageSegment& s = segments[line.segment_index];
    const bool on_edge = std::any_of(projected.begin(), projected.end(), [&](const Segment2& e) { return runsAlong(s, e); });
    if (on_edge) truth.edge = eval::matchToNearestSegment(A, B, edges);
    out.push_back(truth);
  }
  return out;
}

}  // namespace

SimFusionRun runSimulatedFusion(const SimFusionOptions& o) {
  sim::SimOptions sim_options;
  sim_options.seed = o.seed;
  sim_options.duration = o.start + o.duration + 1.0;
  const sim::Scenario scenario = sim::makeScenario(o.scenario, sim_options);
  const sim::LidarSimulator lidar_sim(scenario);
  const sim::CameraRenderer renderer(scenario);
  const Eigen::Isometry3d T_camera_lidar =
      o.extrinsic_error ? sim::perturbExtrinsics(scenario.rig.T_camera_lidar(), *o.extrinsic_error, o.seed)
                        : scenario.rig.T_camera_lidar();

  SimFusionRun run;
  for (const sim::WorldEdge& e : scenario.world.edges()) run.edges.push_back({e.a, e.b});
  lidar::LidarOdometry odometry(o.lidar);
  FusionStep step(scenario.camera.camera, T_camera_lidar, o.fusion);
  visual::LineExtractor extractor(o.lines);
  const double sweep = lidar_sim.sweepDuration();
  const double frame_period = 1.0 / scenario.camera.rate_hz;
  // Sweeps on the simulator's own grid of start times.
  double t_sweep = scenario.lidar.start_offset + std::ceil((o.start - scenario.lidar.start_offset) / sweep) * sweep;
  double previous_end = t_sweep;
  const double measure_from = t_sweep + o.warmup_scans * sweep;
  const double measure_to = measure_from + o.duration;
  for (; previous_end < measure_to; t_sweep += sweep) {
    const LidarScan scan = lidar_sim.scanLidar(t_sweep);
    odometry.prepare(scan);
    step.loadScans(odometry);
    const double end = sweepEnd(scan);
    // Camera frames of (previous sweep end, this sweep end] (paper: t_j .. t_{j+1}).
    const double k0 = std::floor((previous_end - scenario.camera.start_offset) / frame_period) + 1;
    for (double k = k0;; ++k) {
      const double t = scenario.camera.start_offset + k * frame_period;
      if (t > end) break;
      if (t < measure_from || t >= measure_to || static_cast<long>(k) % o.camera_every != 0) continue;
      const cv::Mat image = renderer.renderImage(t);
      std::vector<visual::RawSegment> raw;
      cv::Mat unused;
      extractor.extract(image, raw, unused);
      SimFusionFrame frame;
      frame.t = t;
      const std::vector<ImageSegment> segments = toImageSegments(raw);
      frame.segments = segments.size();
      frame.output = step.processImage(t, segments, odometry);
      frame.truth = measure(frame.output.result, segments, scenario.T_world_camera(t), scenario.camera.camera,
                            scenario.world, run.edges);
      run.lidar_points_changed += frame.output.lidar_points_changed;
      if (o.on_frame) o.on_frame(frame, image, step);
      run.frames.push_back(std::move(frame));
    }
    previous_end = end;
    odometry.registerScan();
  }
  return run;
}

}  // namespace lvslam::fusion::testing
