#pragma once
// One match per frame feature: where several query features matched the
// same frame feature, the closest in descriptor distance keeps it.
#include <cstddef>
#include <vector>

namespace lvslam::visual {

// Match: a struct with `index2` (the frame side, < frame_size) and `distance`.
template <typename Match>
std::vector<Match> uniqueMatches(const std::vector<Match>& matches, std::size_t frame_size) {
  std::vector<int> owner(frame_size, -1);
  for (std::size_t m = 0; m < matches.size(); ++m) {
    int& o = owner[static_cast<std::size_t>(matches[m].index2)];
    if (o < 0 || matches[m].distance < matches[static_cast<std::size_t>(o)].distance) o = static_cast<int>(m);
  }
  std::vector<Match> out;
  for (std::size_t m = 0; m < matches.size(); ++m)
    if (owner[static_cast<std::size_t>(matches[m].index2)] == static_cast<int>(m)) out.push_back(matches[m]);
  return out;
}

}  // namespace lvslam::visual
