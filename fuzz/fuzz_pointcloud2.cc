// Fuzz harness: a ROS1-serialized sensor_msgs/PointCloud2 (io/pointcloud2_decoder.h).
#include <vector>

#include "fuzz_input.h"
#include "lvslam/io/pointcloud2_decoder.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::uint8_t> message(data, data + size);
  lvslam::fuzz::expectOnlyLvslamErrors([&] {
    lvslam::DecodedScan decoded = lvslam::decodePointCloud2(message, "fuzz.bag /points");
    if (decoded.time_reference) lvslam::restampScan(decoded.scan, *decoded.time_reference);
  });
  return 0;
}
