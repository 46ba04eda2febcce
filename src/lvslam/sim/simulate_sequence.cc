#include "lvslam/sim/simulate_sequence.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"
#include "lvslam/io/atomic_folder.h"
#include "lvslam/io/sequence_writer.h"
#include "lvslam/sim/camera_renderer.h"
#include "lvslam/sim/counter_random.h"
#include "lvslam/sim/lidar_simulator.h"

namespace lvslam::sim {

namespace {

Eigen::Vector3d randomUnitVector(CounterRandom& rng) {
  Eigen::Vector3d v;
  do {
    v = Eigen::Vector3d(rng.normal(), rng.normal(), rng.normal());
  } while (v.norm() < 1e-6);
  return v.normalized();
}

void writeExtrinsicsTruth(const std::string& path, const Eigen::Isometry3d& truth, const SimOptions& options) {
  const ExtrinsicError e = options.extrinsic_error.value_or(ExtrinsicError{});
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::Comment("True camera-LiDAR extrinsics of this simulated sequence; sequence.yaml holds a perturbed copy "
                       "when the simulation was asked for an extrinsic error.");
  out << YAML::BeginMap << YAML::Key << "T_camera_lidar" << YAML::Value << YAML::Flow << YAML::BeginSeq;
  const Eigen::Matrix4d M = truth.matrix();
  for (int i = 0; i < 16; ++i) out << M(i / 4, i % 4);
  out << YAML::EndSeq;
  out << YAML::Key << "perturbation" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "rotation_deg" << YAML::Value << e.rotation_deg;
  out << YAML::Key << "translation_m" << YAML::Value << e.translation_m;
  out << YAML::EndMap << YAML::EndMap;
  std::ofstream file(path);
  file << out.c_str() << "\n";
  if (!file) throw Error(path, "cannot write file");
}

SequenceInfo makeInfo(const Scenario& scenario, const Eigen::Isometry3d& T_camera_lidar) {
  SequenceInfo info;
  info.name = scenario.options.family.empty()
                  ? fmt::format("sim_{}{}_seed{}", scenario.name, scenario.options.night ? "_night" : "",
                                scenario.options.seed)
                  : fmt::format("sim_{}_seed{}", scenario.options.family, scenario.options.seed);
  info.camera = CameraInfo{scenario.camera.camera, scenario.camera.rate_hz};
  LidarInfo lidar;
  lidar.rings = static_cast<int>(scenario.lidar.elevations_deg.size());
  lidar.rate_hz = scenario.lidar.rate_hz;
  lidar.time_reference = TimeReference::kStart;
  info.lidar = lidar;
  info.T_camera_lidar = T_camera_lidar;
  info.groundtruth_frame = GroundTruthFrame::kCamera;
  return info;
}

// The fixed-rate grid and every sensor time, in order. Evaluation associates
// an estimate with the nearest ground-truth time (as evo does); on the grid
// alone an image sits up to 2.5 ms from it, which at 1 m/s is 2.5 mm of error
// that no estimator made.
std::vector<double> groundTruthTimes(double duration, std::vector<double> sensor_times) {
  const int grid = static_cast<int>(std::floor(duration * kGroundTruthRateHz)) + 1;
  for (int i = 0; i < grid; ++i) sensor_times.push_back(i / kGroundTruthRateHz);
  std::sort(sensor_times.begin(), sensor_times.end());
  // A sensor time on the grid (within the 1 ns TUM files resolve) is written once.
  const auto same = [](double a, double b) { return b - a < 1e-9; };
  sensor_times.erase(std::unique(sensor_times.begin(), sensor_times.end(), same), sensor_times.end());
  return sensor_times;
}

bool within(const std::optional<TimeInterval>& interval, double t) {
  return interval && t >= interval->begin && t <= interval->end;
}

}  // namespace

Eigen::Isometry3d perturbExtrinsics(const Eigen::Isometry3d& T_camera_lidar, const ExtrinsicError& error,
                                    std::uint64_t seed) {
  CounterRandom rng(seed, RandomStream::kExtrinsics, 0);
  const Eigen::Vector3d axis = randomUnitVector(rng);
  const Eigen::Vector3d direction = randomUnitVector(rng);
  const Eigen::Matrix3d R_error = expSO3(error.rotation_deg * M_PI / 180.0 * axis);
  return makePose(R_error * T_camera_lidar.linear(),
                  T_camera_lidar.translation() + error.translation_m * direction);
}

bool simulateSequenceOnce(const SimOptions& options, const std::string& out_dir,
                          const std::function<void()>& announce) {
  namespace fs = std::filesystem;
  const fs::path dir(out_dir);
  if (fs::exists(dir / "sequence.yaml")) return false;
  if (announce) announce();
  // Whole or not at all, as the converters write (a killed run leaves only
  // a marked "<dir>.partial", replaced next time).
  writeFolderAtomically(out_dir, [&](const std::string& partial) { simulateSequence(options, partial); });
  return true;
}

SimulationSummary simulateSequence(const SimOptions& options, const std::string& out_dir) {
  const Scenario scenario = makeScenario(options);
  const Eigen::Isometry3d truth = scenario.rig.T_camera_lidar();
  const Eigen::Isometry3d written =
      options.extrinsic_error ? perturbExtrinsics(truth, *options.extrinsic_error, options.seed) : truth;
  SequenceWriter writer(out_dir, makeInfo(scenario, written));
  writeExtrinsicsTruth((std::filesystem::path(out_dir) / kExtrinsicsTruthFile).string(), truth, options);

  const CameraRenderer renderer(scenario);
  const LidarSimulator lidar(scenario);
  SimulationSummary summary;
  std::vector<double> sensor_times;  // seconds after the start, for the ground truth
  const double camera_period = 1.0 / scenario.camera.rate_hz;
  AutoExposure exposure(scenario.camera.auto_exposure, scenario.camera.exposure, camera_period);
  const double sweep = lidar.sweepDuration();
  // Both streams in time order; a sweep is written once it has ended.
  for (int k = 0, j = 0;;) {
    const double t_image = scenario.camera.start_offset + k * camera_period;
    const double t_scan = scenario.lidar.start_offset + j * sweep;
    const bool image_left = t_image <= options.duration;
    const bool scan_left = t_scan + sweep <= options.duration;
    if (!image_left && !scan_left) break;
    if (image_left && (!scan_left || t_image <= t_scan + sweep)) {
      cv::Mat image = renderer.renderImage(t_image, exposure.current());
      if (within(options.camera_blackout, t_image)) image.setTo(0);
      exposure.update(image);  // the next frame's exposure, from what this one shows
      writer.writeImage(options.start_time + t_image, image);
      sensor_times.push_back(t_image);
      ++k;
    } else {
      if (!within(options.lidar_dropout, t_scan)) {
        LidarScan scan = lidar.scanLidar(t_scan);
        scan.timestamp += options.start_time;
        writer.writeScan(scan);
        sensor_times.push_back(t_scan);
        ++summary.scans;
      }
      ++j;
    }
    summary.images = k;
  }
  Trajectory groundtruth;
  for (const double t : groundTruthTimes(options.duration, sensor_times))
    groundtruth.push_back({options.start_time + t, scenario.T_world_camera(t)});
  writer.writeGroundTruth(groundtruth);
  summary.groundtruth_poses = static_cast<int>(groundtruth.size());
  return summary;
}

}  // namespace lvslam::sim
