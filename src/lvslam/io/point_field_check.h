#pragma once
// point_fields that read but lose quality silently: a misspelt name
// ('tiem') is skipped like any unknown field, and without a per-point time
// the scans are not deskewed. Each is worth one warning, naming the key.
#include <string>
#include <vector>

namespace lvslam {

// The warnings for `point_fields` of `yaml_path` (none when all is well):
// an unknown name close to a known one (with that name), and no 'time'.
std::vector<std::string> pointFieldWarnings(const std::vector<std::string>& point_fields, const std::string& yaml_path);

}  // namespace lvslam
