#pragma once
// Internal to io/ (never include from a public header: the ROS headers are
// heavy). The sensor_msgs types of Debian's libsensor-msgs-dev, made usable
// from C++20, and deserialization of a message's bytes into them.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace lvslam::rosmsg {

// The generated ROS1 message templates use ContainerAllocator::rebind, which
// C++20 removed from std::allocator; this allocator adds it back.
template <class T>
struct Allocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = Allocator<U>;
  };
  Allocator() = default;
  template <class U>
  Allocator(const Allocator<U>&) {}
};

}  // namespace lvslam::rosmsg

#include <ros/serialization.h>
#include <sensor_msgs/CompressedImage.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>

#include "lvslam/core/error.h"

namespace lvslam::rosmsg {

using PointCloud2 = sensor_msgs::PointCloud2_<Allocator<void>>;
using PointField = sensor_msgs::PointField_<Allocator<void>>;
using Image = sensor_msgs::Image_<Allocator<void>>;
using CompressedImage = sensor_msgs::CompressedImage_<Allocator<void>>;

inline double toSeconds(const ros::Time& t) { return static_cast<double>(t.sec) + 1e-9 * static_cast<double>(t.nsec); }

// Throws lvslam::Error(where, ...) when the bytes are too short for a T.
template <class T>
T deserialize(const std::vector<std::uint8_t>& bytes, const std::string& where) {
  T msg;
  try {
    // IStream only reads, despite its non-const pointer.
    ros::serialization::IStream stream(const_cast<std::uint8_t*>(bytes.data()), static_cast<std::uint32_t>(bytes.size()));
    ros::serialization::deserialize(stream, msg);
  } catch (const std::exception& e) {
    throw Error(where, std::string("malformed ") + ros::message_traits::DataType<T>::value() + " message: " + e.what());
  }
  return msg;
}

}  // namespace lvslam::rosmsg
