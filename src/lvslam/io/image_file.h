#pragma once
// An image file as stored (any depth and channel count, as cv::imread with
// IMREAD_UNCHANGED), or one lvslam::Error naming the file and what is wrong:
// missing, a folder, unreadable, empty, a damaged PNG (png_check.h) or
// undecodable. Nothing is printed.
#include <string>

#include <opencv2/core/mat.hpp>

namespace lvslam {

cv::Mat readImageFile(const std::string& path);

}  // namespace lvslam
