#include "live_node.h"

#include <chrono>
#include <iostream>

#include <fmt/format.h>

#include "run_folder.h"
#include "lvslam/core/error.h"
#include "lvslam/system/output_folder.h"

namespace lvslam::ros_node {

namespace {

// The mode the preset's sensors allow, as `lvslam run` picks it.
std::string modeFor(const NodeParams& p) {
  if (p.camera_topic.empty()) return "lidar";
  if (p.lidar_topic.empty()) return "visual";
  return p.mode;
}

system::SystemConfig loadConfig(const NodeParams& p, const std::string& mode) {
  system::SystemConfig config = system::loadRunConfig(p.config_path);
  config.mode = system::parseRunMode(mode, "parameter ~mode");
  config.deterministic = p.deterministic;
  config.realtime = false;  // the topics already arrive at the sensors' pace
  return config;
}

Recording liveRecording(const NodeParams& p, LiveSensorSource*& source) {
  LiveSourceOptions options;
  options.calibration = p.preset.calibration();
  options.camera = !p.camera_topic.empty();
  options.lidar = !p.lidar_topic.empty();
  options.capacity = p.queue_size;
  options.max_wait_s = p.max_wait_s;
  auto live = std::make_unique<LiveSensorSource>(options);
  source = live.get();
  Recording recording;
  recording.name = "live:" + p.preset.name;
  recording.source = std::move(live);
  if (!p.groundtruth_path.empty()) {
    recording.ground_truth = readTum(p.groundtruth_path);
    recording.ground_truth_frame = p.preset.groundtruth_frame.value_or(GroundTruthFrame::kCamera);
    recording.ground_truth_path = p.groundtruth_path;
  }
  return recording;
}

LiveMapOptions mapOptions(const NodeParams& p) {
  LiveMapOptions options;
  options.voxel_m = p.map_voxel_m;
  return options;
}

}  // namespace

LiveNode::LiveNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh, const NodeParams& params)
    : params_(params),
      config_(loadConfig(params, modeFor(params))),
      mode_(modeFor(params)),
      recording_(liveRecording(params_, source_)),
      problems_([](const std::string& text) { ROS_WARN("%s", text.c_str()); }),
      map_(mapOptions(params), params.preset.T_camera_lidar),
      publisher_(private_nh, params_) {
  if (!params_.out_dir.empty()) {
    system::prepareOutputFolder(params_.out_dir);  // a folder that cannot be written is named now
    if (!params_.camera_topic.empty()) online_poses_.emplace(params_.out_dir + "/trajectory.tum");
  }
  TopicInput::Hooks hooks;
  hooks.image_arrived = [this](double stamp) { latency_.arrived(stamp, PublishLatency::Clock::now()); };
  hooks.scan_accepted = [this](const LidarScan& scan) { map_.addScan(scan); };
  input_ = std::make_unique<TopicInput>(nh, params_, *source_, problems_, std::move(hooks));
  startTimers(private_nh);
  ROS_INFO("lvslam_node: mode %s, preset %s, LiDAR %s, camera %s (%s)%s", mode_.c_str(), params_.preset.name.c_str(),
           params_.lidar_topic.empty() ? "-" : params_.lidar_topic.c_str(),
           params_.camera_topic.empty() ? "-" : params_.camera_topic.c_str(),
           params_.camera_compressed ? "CompressedImage" : "Image", params_.deterministic ? ", deterministic" : "");
}

LiveNode::~LiveNode() {
  if (run_thread_.joinable()) {  // finish() was not reached (an exception): stop the run before its members go
    if (input_) input_->shutdown();
    source_->close();
    run_thread_.join();
  }
}

void LiveNode::startTimers(ros::NodeHandle& private_nh) {
  ros::NodeHandle timers(private_nh);
  timers.setCallbackQueue(&timer_queue_);
  path_timer_ = timers.createWallTimer(ros::WallDuration(params_.path_period_s),
                                       [this](const ros::WallTimerEvent&) { publisher_.publishPath(); });
  map_timer_ = timers.createWallTimer(ros::WallDuration(params_.map_period_s),
                                      [this](const ros::WallTimerEvent&) { publisher_.publishMap(map_.points()); });
  diagnostics_timer_ = timers.createWallTimer(
      ros::WallDuration(1.0), [this](const ros::WallTimerEvent&) { publisher_.publishDiagnostics(problems_.counts()); });
  timer_spinner_ = std::make_unique<ros::AsyncSpinner>(1, &timer_queue_);
  timer_spinner_->start();
}

void LiveNode::start() {
  run_thread_ = std::thread([this] {
    try {
      result_ = system::runRecording(recording_, config_, {}, [this](const system::FrameOutput& f) { onFrame(f); });
    } catch (...) {
      error_ = std::current_exception();
    }
    done_ = true;
  });
}

void LiveNode::onFrame(const system::FrameOutput& frame) {
  publisher_.publishFrame(frame);
  latency_.published(frame.t, PublishLatency::Clock::now(), ros::Time::now().toSec());
  if (!frame.T_world_camera) return;
  if (online_poses_) online_poses_->add({frame.t, *frame.T_world_camera});
  map_.addPose(frame.t, *frame.T_world_camera);
}

void LiveNode::logSummary() const {
  const LiveSourceCounts c = source_->counts();
  std::string dropped;
  for (const auto& [kind, n] : problems_.counts()) dropped += fmt::format("{}{} {}", dropped.empty() ? "" : ", ", n, kind);
  ROS_INFO("lvslam_node: %zu sensor items received, %zu handed to the system; dropped: %s", c.queued + c.late + c.out_of_order,
           c.handed_on, dropped.empty() ? "none" : dropped.c_str());
  ROS_INFO("lvslam_node: %s", formatLatency(latency_.summary()).c_str());
}

int LiveNode::finish() {
  input_->shutdown();
  source_->close();  // the system takes what is queued, then ends its run
  run_thread_.join();
  timer_spinner_->stop();
  publisher_.publishPath();
  publisher_.publishDiagnostics(problems_.counts());
  online_poses_.reset();
  logSummary();
  if (error_) {
    try {
      std::rethrow_exception(error_);
    } catch (const std::exception& e) {
      ROS_ERROR("lvslam_node: the system failed: %s", e.what());
    }
    return 1;
  }
  const system::RunResult& run = *result_;
  std::vector<Eigen::Vector3f> map_points;
  for (const PlyPoint& p : run.output.lidar_map) map_points.push_back(p.p);
  if (!map_points.empty()) publisher_.publishMap(map_points);  // the system's own map replaces the live one
  publisher_.publishLines(run.output.lines_world);
  if (params_.out_dir.empty()) return 0;
  try {
    apps::finishRunFolder(params_.out_dir, recording_, std::move(*result_), mode_, params_.deterministic);
  } catch (const Error& e) {
    ROS_ERROR("lvslam_node: %s", e.what());
    return 2;
  } catch (const std::exception& e) {
    ROS_WARN("lvslam_node: %s; nothing written to %s", e.what(), params_.out_dir.c_str());
    return 1;
  }
  std::cout.flush();
  return 0;
}

}  // namespace lvslam::ros_node
