// Test helper: records nav_msgs/Odometry from a topic as a TUM trajectory
// (one line per message, flushed at once, so a killed recorder keeps them),
// and the square roots of the pose covariance's diagonal (time, then x, y, z
// in m and the rotations about them in rad) beside it.
//   odometry_recorder TOPIC OUT.tum SIGMAS.txt
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "ros_messages.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "odometry_recorder", ros::init_options::AnonymousName);
  if (argc != 4) {
    fmt::print(stderr, "usage: odometry_recorder TOPIC OUT.tum SIGMAS.txt\n");
    return 2;
  }
  std::ofstream out(argv[2]), sigmas(argv[3]);
  ros::NodeHandle nh;
  using lvslam::ros_node::Odometry;
  const auto record = [&out, &sigmas](const boost::shared_ptr<const Odometry>& m) {
    const auto& p = m->pose.pose;
    out << fmt::format("{:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f} {:.9f}\n", m->header.stamp.toSec(),
                       p.position.x, p.position.y, p.position.z, p.orientation.x, p.orientation.y, p.orientation.z,
                       p.orientation.w)
        << std::flush;
    const auto& c = m->pose.covariance;
    sigmas << fmt::format("{:.9f} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g} {:.9g}\n", m->header.stamp.toSec(),
                          std::sqrt(c[0]), std::sqrt(c[7]), std::sqrt(c[14]), std::sqrt(c[21]), std::sqrt(c[28]),
                          std::sqrt(c[35]))
           << std::flush;
  };
  const ros::Subscriber sub = nh.subscribe<Odometry>(argv[1], 1000, record, ros::VoidConstPtr(),
                                                     ros::TransportHints().tcpNoDelay());
  ros::spin();
  return 0;
}
