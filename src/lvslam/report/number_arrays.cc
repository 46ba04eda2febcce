#include "lvslam/report/number_arrays.h"

#include <cmath>

#include <fmt/format.h>

namespace lvslam::report {

std::string fixedArray(const std::vector<double>& values, int decimals) {
  std::string out = "[";
  out.reserve(values.size() * (decimals + 4));
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i) out += ',';
    if (!std::isfinite(values[i])) {
      out += "null";
      continue;
    }
    std::string number = fmt::format("{:.{}f}", values[i], decimals);
    if (number.find('.') != std::string::npos) {
      while (number.back() == '0') number.pop_back();
      if (number.back() == '.') number.pop_back();
    }
    if (number == "-0") number = "0";
    out += number;
  }
  return out + "]";
}

}  // namespace lvslam::report
