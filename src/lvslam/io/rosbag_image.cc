#include "lvslam/io/rosbag_image.h"

#include <algorithm>
#include <cctype>
#include <string_view>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lvslam/core/error.h"
#include "lvslam/io/png_check.h"
#include "lvslam/io/rosbag_msgs.h"

namespace lvslam {

ImageFrame decodeRosImage(const std::vector<std::uint8_t>& serialized, const std::string& where) {
  const auto msg = rosmsg::deserialize<rosmsg::Image>(serialized, where);
  const std::string encoding = msg.encoding.c_str();
  int channels = 0;
  if (encoding == "mono8" || encoding == "8UC1") channels = 1;
  else if (encoding == "bgr8" || encoding == "rgb8" || encoding == "8UC3") channels = 3;
  else
    throw Error(where, fmt::format("unsupported image encoding '{}' (supported: mono8, bgr8, rgb8)", encoding));
  const std::uint64_t row_bytes = static_cast<std::uint64_t>(msg.width) * channels;
  if (msg.width == 0 || msg.height == 0 || msg.step < row_bytes ||
      static_cast<std::uint64_t>(msg.step) * msg.height > msg.data.size())
    throw Error(where, fmt::format("image {} x {} {} with step {} does not fit its {} data bytes", msg.width,
                                   msg.height, encoding, msg.step, msg.data.size()));
  const cv::Mat view(static_cast<int>(msg.height), static_cast<int>(msg.width), CV_8UC(channels),
                     const_cast<std::uint8_t*>(msg.data.data()), msg.step);
  ImageFrame frame{rosmsg::toSeconds(msg.header.stamp), {}};
  if (encoding == "rgb8") cv::cvtColor(view, frame.image, cv::COLOR_RGB2BGR);
  else view.copyTo(frame.image);
  return frame;
}

ImageFrame decodeRosCompressedImage(const std::vector<std::uint8_t>& serialized, const std::string& where) {
  const auto msg = rosmsg::deserialize<rosmsg::CompressedImage>(serialized, where);
  std::string format = msg.format.c_str();
  std::transform(format.begin(), format.end(), format.begin(), [](unsigned char c) { return std::tolower(c); });
  // image_transport writes e.g. "jpeg", "png" or "bgr8; jpeg compressed bgr8".
  if (format.find("jpeg") == std::string::npos && format.find("jpg") == std::string::npos &&
      format.find("png") == std::string::npos)
    throw Error(where, fmt::format("unsupported compressed image format '{}' (supported: jpeg, png)", msg.format.c_str()));
  // A damaged PNG is named here; OpenCV would let libpng print its own line.
  const std::string_view raw(reinterpret_cast<const char*>(msg.data.data()), msg.data.size());
  // OpenCV decodes whatever its signature sniffing finds (JPEG 2000, GDAL's
  // formats; fuzzed, the process ran out of file descriptors): only PNG and
  // JPEG reach it.
  if (!raw.empty() && !raw.starts_with("\x89PNG\r\n\x1a\n") && !raw.starts_with("\xff\xd8\xff"))
    throw Error(where, fmt::format("cannot decode the compressed image: its data is neither PNG nor JPEG (format '{}')",
                                   msg.format.c_str()));
  if (raw.starts_with("\x89PNG")) checkPngChunks(raw, where);
  const cv::Mat bytes(1, static_cast<int>(msg.data.size()), CV_8UC1, const_cast<std::uint8_t*>(msg.data.data()));
  cv::Mat image;
  if (!msg.data.empty()) image = cv::imdecode(bytes, cv::IMREAD_UNCHANGED);
  if (image.empty())
    throw Error(where, fmt::format("cannot decode the {} bytes of a '{}' compressed image", msg.data.size(), msg.format.c_str()));
  if (image.depth() != CV_8U)
    throw Error(where, fmt::format("compressed image '{}' is not 8-bit (only 8-bit gray or colour)", msg.format.c_str()));
  ImageFrame frame{rosmsg::toSeconds(msg.header.stamp), {}};
  if (image.channels() == 4) cv::cvtColor(image, frame.image, cv::COLOR_BGRA2BGR);
  else if (image.channels() == 1 || image.channels() == 3) frame.image = image;
  else throw Error(where, fmt::format("compressed image with {} channels", image.channels()));
  return frame;
}

}  // namespace lvslam
