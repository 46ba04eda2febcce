#include "lvslam/eval/error_statistics.h"

#include <algorithm>
#include <cmath>

namespace lvslam::eval {

namespace {

double median(std::vector<double> values) {
  const std::size_t n = values.size();
  const auto upper = values.begin() + static_cast<std::ptrdiff_t>(n / 2);
  std::nth_element(values.begin(), upper, values.end());
  if (n % 2 == 1) return *upper;
  // The lower middle value is the largest of the lower half.
  const double lower = *std::max_element(values.begin(), upper);
  return 0.5 * (lower + *upper);
}

}  // namespace

ErrorStatistics computeStatistics(const std::vector<double>& errors) {
  ErrorStatistics stats;
  stats.count = errors.size();
  if (errors.empty()) return stats;
  const double n = static_cast<double>(errors.size());
  double sum = 0.0;
  for (const double e : errors) {
    sum += e;
    stats.sse += e * e;
  }
  stats.mean = sum / n;
  stats.rmse = std::sqrt(stats.sse / n);
  double squared_deviation = 0.0;
  for (const double e : errors) squared_deviation += (e - stats.mean) * (e - stats.mean);
  stats.std_dev = std::sqrt(squared_deviation / n);
  const auto [min_it, max_it] = std::minmax_element(errors.begin(), errors.end());
  stats.min = *min_it;
  stats.max = *max_it;
  stats.median = median(errors);
  return stats;
}

}  // namespace lvslam::eval
