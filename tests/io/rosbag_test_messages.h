#pragma once
// Test helpers: ROS messages built field by field and bags written with
// rosbag_storage's own writer (rosbag::Bag in write mode).
#include <cstring>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "lvslam/io/rosbag_msgs.h"

#include <rosbag/bag.h>

namespace lvslam::testing {

inline ros::Time rosTime(double t) {
  ros::Time stamp;
  stamp.fromSec(t);
  return stamp;
}

inline rosmsg::PointField pointField(const std::string& name, std::uint32_t offset, std::uint8_t datatype) {
  rosmsg::PointField f;
  f.name = name.c_str();
  f.offset = offset;
  f.datatype = datatype;
  f.count = 1;
  return f;
}

struct VelodynePoint {
  float x, y, z, intensity;
  std::uint16_t ring;
  float time;
};

// The Velodyne driver's layout: x y z (pad) intensity ring time, point_step 32.
inline rosmsg::PointCloud2 velodyneCloud(double stamp, const std::vector<VelodynePoint>& points) {
  rosmsg::PointCloud2 cloud;
  cloud.header.stamp = rosTime(stamp);
  cloud.header.frame_id = "velodyne";
  cloud.height = 1;
  cloud.width = static_cast<std::uint32_t>(points.size());
  cloud.fields = {pointField("x", 0, 7), pointField("y", 4, 7), pointField("z", 8, 7),
                  pointField("intensity", 16, 7), pointField("ring", 20, 4), pointField("time", 24, 7)};
  cloud.point_step = 32;
  cloud.row_step = 32 * cloud.width;
  cloud.is_dense = false;
  cloud.data.assign(cloud.row_step, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    std::uint8_t* p = cloud.data.data() + 32 * i;
    std::memcpy(p + 0, &points[i].x, 4);
    std::memcpy(p + 4, &points[i].y, 4);
    std::memcpy(p + 8, &points[i].z, 4);
    std::memcpy(p + 16, &points[i].intensity, 4);
    std::memcpy(p + 20, &points[i].ring, 2);
    std::memcpy(p + 24, &points[i].time, 4);
  }
  return cloud;
}

inline rosmsg::Image rawImage(double stamp, const cv::Mat& image, const std::string& encoding) {
  rosmsg::Image msg;
  msg.header.stamp = rosTime(stamp);
  msg.height = static_cast<std::uint32_t>(image.rows);
  msg.width = static_cast<std::uint32_t>(image.cols);
  msg.encoding = encoding.c_str();
  msg.step = static_cast<std::uint32_t>(image.cols * image.elemSize() + 3);  // padded rows
  msg.data.assign(static_cast<std::size_t>(msg.step) * image.rows, 0);
  for (int r = 0; r < image.rows; ++r)
    std::memcpy(msg.data.data() + r * msg.step, image.ptr(r), image.cols * image.elemSize());
  return msg;
}

inline rosmsg::CompressedImage compressedImage(double stamp, const std::vector<std::uint8_t>& bytes,
                                               const std::string& format) {
  rosmsg::CompressedImage msg;
  msg.header.stamp = rosTime(stamp);
  msg.format = format.c_str();
  msg.data.assign(bytes.begin(), bytes.end());
  return msg;
}

}  // namespace lvslam::testing
