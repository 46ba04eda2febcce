// `lvslam overlay`: runs the LiDAR odometry with the fusion step over a
// sequence folder and writes, for every n-th camera frame, the image with the
// LiDAR features (green planar, red linear, blue other), the LSD segments
// (yellow) and the fusion lines (magenta) drawn over it: how a user checks an
// extrinsic calibration by eye (LiDAR points must sit on the edges they see).
#include <algorithm>
#include <deque>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "command.h"
#include "overlay_image.h"
#include "lvslam/core/error.h"
#include "lvslam/fusion/fusion_step.h"
#include "lvslam/fusion/lidar_bridge.h"
#include "lvslam/io/sequence_reader.h"
#include "lvslam/system/system_config.h"

namespace lvslam::apps {

namespace {

struct OverlayArgs {
  std::string sequence_dir, out_dir, config_path;
  int every = 5;
};

struct OverlayStats {
  std::size_t frames = 0, written = 0, lines = 0, segments = 0, refined = 0;
};

class OverlayRun {
 public:
  OverlayRun(const OverlayArgs& args, const system::SystemConfig& config, const PinholeCamera& camera,
             const Eigen::Isometry3d& T_camera_lidar)
      : args_(args),
        camera_(camera),
        odometry_(config.lidar),
        step_(camera, T_camera_lidar, config.fusion),
        extractor_(lineConfig(camera, config.fusion)) {}

  // The scan with the camera frames of its interval (previous sweep end, this sweep end].
  void runScan(const LidarScan& scan, std::deque<ImageFrame>& images) {
    odometry_.prepare(scan);
    step_.loadScans(odometry_);
    const double end = fusion::sweepEnd(scan);
    while (!images.empty() && images.front().timestamp <= end) {
      processImage(images.front());
      images.pop_front();
    }
    odometry_.registerScan();
  }

  const OverlayStats& stats() const { return stats_; }

 private:
  // LSD as the visual subsystem runs it, without descriptors, down to the fusion's shortest segment.
  static visual::LineExtractorConfig lineConfig(const PinholeCamera& camera, const fusion::FusionConfig& fusion) {
    visual::LineExtractorConfig c;
    c.compute_descriptors = false;
    c.min_length_ratio = fusion.min_segment_length_px / std::min(camera.width(), camera.height());
    return c;
  }

  void processImage(const ImageFrame& frame) {
    cv::Mat gray = frame.image;
    if (gray.channels() == 3) cv::cvtColor(frame.image, gray, cv::COLOR_BGR2GRAY);
    std::vector<visual::RawSegment> raw;
    cv::Mat unused;
    extractor_.extract(gray, raw, unused);
    const std::vector<fusion::ImageSegment> segments = fusion::toImageSegments(raw);
    const fusion::FusionFrameOutput out = step_.processImage(frame.timestamp, segments, odometry_);
    stats_.lines += out.result.lines.size();
    stats_.segments += segments.size();
    stats_.refined += out.lidar_points_changed;
    if (stats_.frames++ % static_cast<std::size_t>(args_.every) != 0) return;
    cv::Mat canvas = drawOverlayImage(frame.image, camera_, step_.framework().featuresInCamera(out.T_world_lidar),
                                      segments, out.result.lines);
    const std::string caption = fmt::format("t {:.3f}  LiDAR {} (green planar, red linear, blue other)  LSD {}  fusion {}",
                                            frame.timestamp, out.result.lidar_features, segments.size(),
                                            out.result.lines.size());
    cv::putText(canvas, caption, {6, 16}, cv::FONT_HERSHEY_SIMPLEX, 0.42, {0, 0, 0}, 3, cv::LINE_AA);
    cv::putText(canvas, caption, {6, 16}, cv::FONT_HERSHEY_SIMPLEX, 0.42, {255, 255, 255}, 1, cv::LINE_AA);
    const auto path = std::filesystem::path(args_.out_dir) / fmt::format("overlay_{:06}.png", stats_.frames - 1);
    if (!cv::imwrite(path.string(), canvas)) throw Error(path.string(), "cannot write the image");
    ++stats_.written;
  }

  OverlayArgs args_;
  PinholeCamera camera_;
  lidar::LidarOdometry odometry_;
  fusion::FusionStep step_;
  visual::LineExtractor extractor_;
  OverlayStats stats_;
};

int runOverlay(const OverlayArgs& args) {
  if (args.every < 1) throw Error("--every", "must be at least 1");
  SequenceReader reader(args.sequence_dir);
  if (!reader.hasCamera() || !reader.hasLidar())
    throw Error(args.sequence_dir, "lvslam overlay needs a sequence with a camera and a LiDAR");
  const Calibration calibration = reader.calibration();
  std::filesystem::create_directories(args.out_dir);
  OverlayRun run(args, system::loadRunConfig(args.config_path), *calibration.camera, calibration.T_camera_lidar);
  // A scan waits until the stream has passed its sweep's end, so that all
  // camera frames of its interval have arrived.
  std::optional<LidarScan> pending;
  std::deque<ImageFrame> images;
  while (auto data = reader.next()) {
    if (auto* image = std::get_if<ImageFrame>(&*data)) {
      images.push_back(std::move(*image));
      continue;
    }
    if (pending) run.runScan(*pending, images);
    pending = std::move(std::get<LidarScan>(*data));
  }
  if (pending) run.runScan(*pending, images);
  const OverlayStats& s = run.stats();
  const double per_frame = s.frames ? 1.0 / static_cast<double>(s.frames) : 0.0;
  std::cout << fmt::format(
      "{} camera frames fused ({:.1f} LSD segments, {:.1f} fusion lines per frame; {} LiDAR points given d_v_mean); "
      "wrote {} images to {}\n",
      s.frames, s.segments * per_frame, s.lines * per_frame, s.refined, s.written, args.out_dir);
  return 0;
}

}  // namespace

void addOverlayCommand(CLI::App& app, CommandAction& action) {
  CLI::App* cmd = app.add_subcommand(
      "overlay", "Draw LiDAR features, LSD segments and fusion lines over the camera frames of a sequence "
                 "(LiDAR odometry with the fusion step), to check the extrinsic calibration by eye");
  auto args = std::make_shared<OverlayArgs>();
  cmd->add_option("--sequence", args->sequence_dir, "Sequence folder (docs/sequence-format.md)")->required();
  cmd->add_option("--out", args->out_dir, "Folder for the PNG images")->required();
  cmd->add_option("--every", args->every, "Write every n-th camera frame")->default_val(5);
  cmd->add_option("--config", args->config_path, "YAML configuration (e.g. config/sim.yaml; its lidar: and fusion: sections are used) over config/advanced.yaml");
  cmd->callback([&action, args] { action = [args] { return runOverlay(*args); }; });
}

}  // namespace lvslam::apps
