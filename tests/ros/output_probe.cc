// Test helper: listens to what lvslam_node publishes besides its odometry
// and, when stopped (SIGINT), writes one line per output to a file:
//   path POSES / map POINTS / lines SEGMENTS / diagnostics MESSAGES SWITCHES / tf_static PARENT>CHILD ...
//   / tf PARENT>CHILD ... (each pair once)
// (the last message of each, as a subscriber that joined at any time sees it).
//   output_probe NODE_NAMESPACE OUT.txt      e.g. output_probe /lvslam probe.txt
#include <fstream>
#include <mutex>
#include <set>
#include <string>

#include <fmt/format.h>

#include "ros_messages.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "output_probe", ros::init_options::AnonymousName);
  if (argc != 3) {
    fmt::print(stderr, "usage: output_probe NODE_NAMESPACE OUT.txt\n");
    return 2;
  }
  using namespace lvslam::ros_node;
  const std::string ns = argv[1];
  std::mutex mutex;
  std::size_t path = 0, map = 0, lines = 0, diagnostics = 0;
  std::string switches = "-", tf_static;
  std::set<std::string> tf;
  ros::NodeHandle nh;
  const auto s1 = nh.subscribe<Path>(ns + "/path", 10, [&](const boost::shared_ptr<const Path>& m) {
    std::lock_guard lock(mutex);
    path = m->poses.size();
  });
  const auto s2 = nh.subscribe<PointCloud2>(ns + "/map", 10, [&](const boost::shared_ptr<const PointCloud2>& m) {
    std::lock_guard lock(mutex);
    map = static_cast<std::size_t>(m->width) * m->height;
  });
  const auto s3 = nh.subscribe<MarkerArray>(ns + "/lines", 10, [&](const boost::shared_ptr<const MarkerArray>& m) {
    std::lock_guard lock(mutex);
    lines = 0;
    for (const auto& marker : m->markers) lines += marker.points.size() / 2;
  });
  const auto s4 = nh.subscribe<DiagnosticArray>("/diagnostics", 100, [&](const boost::shared_ptr<const DiagnosticArray>& m) {
    std::lock_guard lock(mutex);
    for (const auto& status : m->status) {
      if (std::string(status.name.c_str()) != "lvslam: detection module") continue;
      ++diagnostics;
      for (const auto& kv : status.values)
        if (std::string(kv.key.c_str()) == "switches") switches = kv.value.c_str();
    }
  });
  const auto s5 = nh.subscribe<TFMessage>("/tf_static", 10, [&](const boost::shared_ptr<const TFMessage>& m) {
    std::lock_guard lock(mutex);
    for (const auto& t : m->transforms) tf_static += fmt::format(" {}>{}", t.header.frame_id.c_str(), t.child_frame_id.c_str());
  });
  const auto s6 = nh.subscribe<TFMessage>("/tf", 100, [&](const boost::shared_ptr<const TFMessage>& m) {
    std::lock_guard lock(mutex);
    for (const auto& t : m->transforms) tf.insert(fmt::format("{}>{}", t.header.frame_id.c_str(), t.child_frame_id.c_str()));
  });
  ros::spin();
  std::lock_guard lock(mutex);
  std::string tf_pairs;
  for (const std::string& pair : tf) tf_pairs += " " + pair;
  std::ofstream(argv[2]) << fmt::format("path {}\nmap {}\nlines {}\ndiagnostics {} {}\ntf_static{}\ntf{}\n", path, map,
                                        lines, diagnostics, switches, tf_static, tf_pairs);
  return 0;
}
