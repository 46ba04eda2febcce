#include "lvslam/core/timestamp.h"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

namespace lvslam {

std::string formatTimestamp(double t) { return fmt::format("{:.9f}", t); }

bool parseTimestamp(const std::string& text, double& t) {
  if (text.empty()) return false;
  char* end = nullptr;
  t = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(t);
}

}  // namespace lvslam
