#include "lvslam/io/point_field_check.h"

#include <algorithm>
#include <array>
#include <numeric>

#include <fmt/format.h>

namespace lvslam {

namespace {

constexpr std::array<const char*, 6> kKnownFields{"x", "y", "z", "intensity", "time", "ring"};

// Levenshtein distance: insertions, deletions and substitutions.
std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), 0);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

}  // namespace

std::vector<std::string> pointFieldWarnings(const std::vector<std::string>& point_fields, const std::string& yaml_path) {
  std::vector<std::string> warnings;
  const auto has = [&](const std::string& name) {
    return std::find(point_fields.begin(), point_fields.end(), name) != point_fields.end();
  };
  for (const std::string& field : point_fields) {
    if (std::find(kKnownFields.begin(), kKnownFields.end(), field) != kKnownFields.end()) continue;
    for (const char* known : kKnownFields) {
      // Close, not already present, and not a one-letter name one edit from anything.
      if (has(known) || std::string(known).size() < 3 || editDistance(field, known) > 2) continue;
      warnings.push_back(fmt::format("{}: key 'lidar.point_fields': unknown field '{}' is skipped; did you mean '{}'?",
                                     yaml_path, field, known));
      break;
    }
  }
  if (!has("time"))
    warnings.push_back(fmt::format("{}: key 'lidar.point_fields': no per-point 'time': the scans are not deskewed "
                                   "(motion within a sweep stays in the points)",
                                   yaml_path));
  return warnings;
}

}  // namespace lvslam
