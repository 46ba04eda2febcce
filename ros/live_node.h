#pragma once
// lvslam_node's run: the live source fed by the topics, the system run over
// it exactly as `lvslam run` runs a recording (system::runRecording, same
// threads and queues) on a thread of its own, each frame's online output
// published as it is made and streamed into trajectory.tum, and on finish()
// the run folder written as `lvslam run` writes it.
#include <atomic>
#include <exception>
#include <memory>
#include <optional>
#include <thread>

#include <ros/callback_queue.h>
#include <ros/ros.h>

#include "input_problems.h"
#include "live_map.h"
#include "node_params.h"
#include "output_publisher.h"
#include "publish_latency.h"
#include "topic_input.h"
#include "lvslam/io/live_source.h"
#include "lvslam/io/recording.h"
#include "lvslam/io/tum.h"
#include "lvslam/system/run_recording.h"

namespace lvslam::ros_node {

class LiveNode {
 public:
  // Throws lvslam::Error on a bad configuration or output folder.
  LiveNode(ros::NodeHandle& nh, ros::NodeHandle& private_nh, const NodeParams& params);
  ~LiveNode();

  void start();
  // The system stopped on its own (an error in a subsystem).
  bool stopped() const { return done_; }
  // Stops the input, lets the system finish what is queued (published as
  // usual), writes the run folder. Exit code: 0 written, 1 no result or a
  // failed run, 2 the outputs could not be written.
  int finish();

 private:
  void onFrame(const system::FrameOutput& frame);
  void startTimers(ros::NodeHandle& private_nh);
  void logSummary() const;

  NodeParams params_;
  system::SystemConfig config_;
  std::string mode_;
  LiveSensorSource* source_ = nullptr;  // owned by recording_
  Recording recording_;
  InputProblems problems_;
  PublishLatency latency_;
  LiveMap map_;
  OutputPublisher publisher_;
  std::unique_ptr<TopicInput> input_;
  std::optional<TumStream> online_poses_;
  // The periodic publications run on their own queue and thread, so that the
  // map's copy never delays the sensor callbacks.
  ros::CallbackQueue timer_queue_;
  std::unique_ptr<ros::AsyncSpinner> timer_spinner_;
  ros::WallTimer path_timer_, map_timer_, diagnostics_timer_;
  std::thread run_thread_;
  std::optional<system::RunResult> result_;
  std::exception_ptr error_;
  std::atomic<bool> done_{false};
};

}  // namespace lvslam::ros_node
