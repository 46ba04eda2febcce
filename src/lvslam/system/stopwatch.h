#pragma once
// Wall time of a stage, in milliseconds, for stats.json.
#include <chrono>

namespace lvslam::system {

class Stopwatch {
 public:
  double ms() const { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count(); }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace lvslam::system
