#pragma once
// Hamming distance of 256-bit binary descriptors (ORB and LBD rows, 32 bytes).
#include <cstdint>
#include <cstring>

#include <opencv2/core.hpp>

namespace lvslam::visual {

inline int hammingDistance256(const uint8_t* a, const uint8_t* b) {
  int distance = 0;
  for (int i = 0; i < 4; ++i) {
    uint64_t x = 0, y = 0;
    std::memcpy(&x, a + 8 * i, 8);
    std::memcpy(&y, b + 8 * i, 8);
    distance += __builtin_popcountll(x ^ y);
  }
  return distance;
}

// Rows of two CV_8U descriptor matrices with 32 columns.
inline int descriptorDistance(const cv::Mat& a, int row_a, const cv::Mat& b, int row_b) {
  return hammingDistance256(a.ptr<uint8_t>(row_a), b.ptr<uint8_t>(row_b));
}

}  // namespace lvslam::visual
