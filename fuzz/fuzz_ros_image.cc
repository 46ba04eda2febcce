// Fuzz harness: ROS1-serialized sensor_msgs/Image and CompressedImage
// (io/rosbag_image.h); the first byte chooses which.
#include <vector>

#include "fuzz_input.h"
#include "lvslam/io/rosbag_image.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::vector<std::uint8_t> message(data + 1, data + size);
  lvslam::fuzz::expectOnlyLvslamErrors([&] {
    if (data[0] % 2 == 0)
      (void)lvslam::decodeRosImage(message, "fuzz.bag /image");
    else
      (void)lvslam::decodeRosCompressedImage(message, "fuzz.bag /image_compressed");
  });
  return 0;
}
