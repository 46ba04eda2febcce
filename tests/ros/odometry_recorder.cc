// Test helper: records nav_msgs/Odometry from a topic as a TUM trajectory
// (one line per message, flushed at once, so a killed recorder keeps them).
//   odometry_recorder TOPIC OUT.tum
#include <fstream>

#include <fmt/format.h>

#include "ros_messages.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "odometry_recorder", ros::init_options::AnonymousName);
  if (argc != 3) {
    fmt::print(stderr, "usage: odometry_recorder TOPIC OUT.tum\n");
    return 2;
  }
  std::ofstream out(argv[2]);
  ros::NodeHandle nh;
  using lvslam::ros_node::Odometry;
  const auto record = [&out](const boost::shared_ptr<const Odometry>& m) {
    const auto& p = m->pose.pose;
    out << fmt::format("{:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f}\n", m->header.stamp.toSec(),
                       p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y, p.orientation.z,
                       p.orientation.w)
        << std::flush;
  };
  const ros::Subscriber sub = nh.subscribe<Odometry>(argv[1], 1000, record, ros::VoidConstPtr(),
                                                     ros::TransportHints().tcpNoDelay());
  ros::spin();
  return 0;
}
