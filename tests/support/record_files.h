#pragma once
// Records of a test, to and from the pipeline's record files.
#include <vector>

#include "lvslam/system/record_file.h"

namespace lvslam::testing {

template <typename T>
system::RecordFile<T> recordFileOf(const std::vector<T>& records) {
  system::RecordFile<T> file;
  for (const T& record : records) file.push_back(record);
  return file;
}

template <typename T>
std::vector<T> vectorOf(const system::RecordFile<T>& file) {
  return std::vector<T>(file.begin(), file.end());
}

}  // namespace lvslam::testing
