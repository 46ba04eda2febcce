// Test helper: publishes bad input on lvslam_node's topics, each kind three
// times: an empty cloud, a cloud without per-point time, a cloud that lacks
// z, an image in an encoding lvslam does not read, an image whose size is
// not the calibration's, and a valid scan followed by one stamped earlier.
//   bad_input_publisher LIDAR_TOPIC CAMERA_TOPIC WIDTH HEIGHT
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "ros_messages.h"

namespace {

using namespace lvslam::ros_node;

PointField field(const char* name, std::uint32_t offset) {
  PointField f;
  f.name = name;
  f.offset = offset;
  f.datatype = PointField::FLOAT32;
  f.count = 1;
  return f;
}

// `names`: float32 fields in this order; every point (i, 1, 0.5, i * 1e-4 ...).
PointCloud2 cloud(double stamp, const std::vector<const char*>& names, std::uint32_t points) {
  PointCloud2 c;
  c.header.stamp = toRosTime(stamp);
  c.header.frame_id = "velodyne";
  c.height = 1;
  c.width = points;
  for (std::uint32_t i = 0; i < names.size(); ++i) c.fields.push_back(field(names[i], 4 * i));
  c.point_step = static_cast<std::uint32_t>(4 * names.size());
  c.row_step = c.point_step * points;
  c.data.resize(c.row_step);
  for (std::uint32_t i = 0; i < points; ++i)
    for (std::uint32_t k = 0; k < names.size(); ++k) {
      const float v = std::string(names[k]) == "time" ? 1e-4f * static_cast<float>(i) : 1.0f + static_cast<float>(i + k);
      std::memcpy(c.data.data() + i * c.point_step + 4 * k, &v, 4);
    }
  return c;
}

Image image(double stamp, std::uint32_t width, std::uint32_t height, const char* encoding, std::uint32_t bytes_per_pixel) {
  Image m;
  m.header.stamp = toRosTime(stamp);
  m.width = width;
  m.height = height;
  m.encoding = encoding;
  m.step = width * bytes_per_pixel;
  m.data.assign(static_cast<std::size_t>(m.step) * height, 128);
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  ros::init(argc, argv, "bad_input_publisher", ros::init_options::AnonymousName);
  if (argc != 5) {
    fmt::print(stderr, "usage: bad_input_publisher LIDAR_TOPIC CAMERA_TOPIC WIDTH HEIGHT\n");
    return 2;
  }
  const auto width = static_cast<std::uint32_t>(std::stoul(argv[3])), height = static_cast<std::uint32_t>(std::stoul(argv[4]));
  ros::NodeHandle nh;
  ros::Publisher lidar = nh.advertise<PointCloud2>(argv[1], 100);
  ros::Publisher camera = nh.advertise<Image>(argv[2], 100);
  for (int i = 0; i < 100 && (lidar.getNumSubscribers() == 0 || camera.getNumSubscribers() == 0); ++i)
    ros::WallDuration(0.1).sleep();
  if (lidar.getNumSubscribers() == 0 || camera.getNumSubscribers() == 0) {
    fmt::print(stderr, "bad_input_publisher: nobody subscribed to {} and {}\n", argv[1], argv[2]);
    return 1;
  }
  double t = 100.0;
  for (int round = 0; round < 3; ++round) {
    lidar.publish(cloud(t += 0.1, {"x", "y", "z", "time"}, 0));                 // empty cloud
    lidar.publish(cloud(t += 0.1, {"x", "y", "z", "intensity"}, 50));          // no per-point time
    lidar.publish(cloud(t += 0.1, {"x", "y", "time"}, 50));                    // no z: undecodable
    camera.publish(image(t += 0.1, width, height, "16UC1", 2));                // unsupported encoding
    camera.publish(image(t += 0.1, width / 2, height / 2, "mono8", 1));        // not the calibration's size
    lidar.publish(cloud(t += 0.1, {"x", "y", "z", "time"}, 50));               // valid
    lidar.publish(cloud(t - 0.05, {"x", "y", "z", "time"}, 50));               // stamped before the previous
    ros::WallDuration(0.2).sleep();
  }
  ros::WallDuration(1.0).sleep();  // let the last messages leave before the connections close
  return 0;
}
