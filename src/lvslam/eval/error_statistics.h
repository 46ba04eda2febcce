#pragma once
// Summary statistics of a list of errors, defined as evo's PE.get_statistic
// defines them (numpy: population std with ddof 0, median of the two middle
// values for an even count).
#include <cstddef>
#include <limits>
#include <vector>

namespace lvslam::eval {

struct ErrorStatistics {
  std::size_t count = 0;
  // NaN while count is 0.
  double rmse = std::numeric_limits<double>::quiet_NaN();
  double mean = std::numeric_limits<double>::quiet_NaN();
  double median = std::numeric_limits<double>::quiet_NaN();
  double std_dev = std::numeric_limits<double>::quiet_NaN();  // population (ddof 0)
  double min = std::numeric_limits<double>::quiet_NaN();
  double max = std::numeric_limits<double>::quiet_NaN();
  double sse = 0.0;
};

ErrorStatistics computeStatistics(const std::vector<double>& errors);

}  // namespace lvslam::eval
