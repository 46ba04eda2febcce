#include "lvslam/io/image_file.h"

#include <filesystem>
#include <iterator>
#include <string_view>

#include <opencv2/imgcodecs.hpp>

#include "lvslam/core/error.h"
#include "lvslam/core/file_access.h"
#include "lvslam/io/png_check.h"

namespace lvslam {

cv::Mat readImageFile(const std::string& path) {
  std::ifstream in = openInputFile(path, "", std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (bytes.empty()) throw Error(path, "empty file (0 bytes)");
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".png") checkPngChunks(bytes, path);
  const cv::Mat raw(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<char*>(bytes.data()));
  cv::Mat image = cv::imdecode(raw, cv::IMREAD_UNCHANGED);
  if (image.empty()) throw Error(path, "cannot decode image");
  return image;
}

}  // namespace lvslam
