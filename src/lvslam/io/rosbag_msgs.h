#pragma once
// Internal to io/ (never include from a public header: the ROS headers are
// heavy). The sensor_msgs types of Debian's libsensor-msgs-dev, made usable
// from C++20, and deserialization of a message's bytes into them.
#include <cstdint>
#include <cstring>
#include <memory>
#include <stdexcept>
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

// Walks the length prefixes of a serialized message without reading it:
// roscpp_serialization resizes a string or a vector to the length the bytes
// claim before it checks that they hold that much (four bytes 0x7f7f7f7f
// allocate 2 GiB), and reads an empty message through a null pointer. Throws
// std::out_of_range when the message is shorter than its lengths say.
class SerializedLengths {
 public:
  explicit SerializedLengths(const std::vector<std::uint8_t>& bytes) : bytes_(bytes) {}
  void skip(std::size_t n) {
    if (n > bytes_.size() - pos_) throw std::out_of_range("a length runs past the end of the message");
    pos_ += n;
  }
  std::uint32_t u32() {
    skip(4);
    std::uint32_t v = 0;
    std::memcpy(&v, bytes_.data() + pos_ - 4, 4);  // little-endian, as ROS1 serializes and this platform is
    return v;
  }
  void bytes() { skip(u32()); }  // a string or a uint8[]
  void header() {  // std_msgs/Header: seq, stamp (sec, nsec), frame_id
    skip(12);
    bytes();
  }

 private:
  const std::vector<std::uint8_t>& bytes_;
  std::size_t pos_ = 0;
};

inline void checkLengths(SerializedLengths& m, const Image*) {
  m.header();
  m.skip(8);  // height, width
  m.bytes();  // encoding
  m.skip(5);  // is_bigendian, step
  m.bytes();  // data
}
inline void checkLengths(SerializedLengths& m, const CompressedImage*) {
  m.header();
  m.bytes();  // format
  m.bytes();  // data
}
inline void checkLengths(SerializedLengths& m, const PointCloud2*) {
  m.header();
  m.skip(8);  // height, width
  for (std::uint32_t i = 0, fields = m.u32(); i < fields; ++i) {
    m.bytes();   // name
    m.skip(9);   // offset, datatype, count
  }
  m.skip(9);  // is_bigendian, point_step, row_step
  m.bytes();  // data
  m.skip(1);  // is_dense
}

// Throws lvslam::Error(where, ...) when the bytes are too short for a T.
template <class T>
T deserialize(const std::vector<std::uint8_t>& bytes, const std::string& where) {
  T msg;
  try {
    SerializedLengths lengths(bytes);
    checkLengths(lengths, static_cast<const T*>(nullptr));
    // IStream only reads, despite its non-const pointer.
    ros::serialization::IStream stream(const_cast<std::uint8_t*>(bytes.data()), static_cast<std::uint32_t>(bytes.size()));
    ros::serialization::deserialize(stream, msg);
  } catch (const std::exception& e) {
    throw Error(where, std::string("malformed ") + ros::message_traits::DataType<T>::value() + " message: " + e.what());
  }
  return msg;
}

}  // namespace lvslam::rosmsg
