#pragma once
// sensor_msgs/Image (mono8, bgr8, rgb8) and sensor_msgs/CompressedImage (JPEG,
// PNG) to an 8-bit gray or BGR ImageFrame stamped with the header stamp.
#include <cstdint>
#include <string>
#include <vector>

#include "lvslam/core/image_frame.h"

namespace lvslam {

// Throw lvslam::Error(where, ...) on another encoding or format (named in the
// message), a step or data size that does not fit the image, or bytes that do
// not decode; `where` names the bag and topic.
ImageFrame decodeRosImage(const std::vector<std::uint8_t>& serialized, const std::string& where);
ImageFrame decodeRosCompressedImage(const std::vector<std::uint8_t>& serialized, const std::string& where);

}  // namespace lvslam
