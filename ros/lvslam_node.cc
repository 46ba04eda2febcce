// lvslam_node: lvslam on live ROS1 topics (README, "Run on a robot").
// SIGINT or SIGTERM (Ctrl-C, roslaunch's shutdown, rosnode kill) ends the
// run the way the end of a recording ends `lvslam run`: what is queued is
// processed and published, then the run folder (~out) is written.
#include <signal.h>

#include <cstdio>
#include <ctime>
#include <memory>

#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include "live_node.h"
#include "node_params.h"
#include "lvslam/core/error.h"

namespace {

// Waits for SIGINT or SIGTERM, or for roscpp or the system to stop.
void waitForStop(const sigset_t& stop_signals, const lvslam::ros_node::LiveNode& node) {
  const timespec poll{0, 200'000'000};
  while (ros::ok() && !node.stopped())
    if (sigtimedwait(&stop_signals, nullptr, &poll) > 0) return;
}

}  // namespace

int main(int argc, char** argv) {
  // The stop signals are taken by sigtimedwait, not a handler (no global
  // flag); blocked before roscpp starts its threads, so they inherit it.
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  ros::init(argc, argv, "lvslam_node", ros::init_options::NoSigintHandler);
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // ROS_INFO lines reach a log file as they are written
  spdlog::set_default_logger(spdlog::stderr_color_mt("lvslam"));  // the library's warnings beside ROS's
  ros::NodeHandle nh, private_nh("~");
  int code = 0;
  try {
    const lvslam::ros_node::NodeParams params = lvslam::ros_node::loadNodeParams(private_nh);
    lvslam::ros_node::LiveNode node(nh, private_nh, params);
    ros::AsyncSpinner spinner(1);  // one thread: each topic's messages in arrival order
    spinner.start();
    node.start();
    waitForStop(stop_signals, node);
    code = node.finish();
    spinner.stop();
  } catch (const lvslam::Error& e) {
    ROS_FATAL("lvslam_node: %s", e.what());
    code = 2;
  }
  ros::shutdown();
  return code;
}
