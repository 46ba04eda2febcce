#include "lvslam/loop/loop_candidates.h"

#include <algorithm>
#include <utility>

namespace lvslam::loop {

std::optional<LoopCandidate> findLoopCandidate(const std::vector<ScanContext>& database,
                                               const std::vector<double>& path_lengths, double exclude_recent_path,
                                               int ring_key_candidates) {
  if (database.size() < 2) return std::nullopt;
  const std::size_t query = database.size() - 1;
  std::vector<std::pair<double, std::size_t>> by_ring_key;
  for (std::size_t i = 0; i < query; ++i)
    if (path_lengths[query] - path_lengths[i] >= exclude_recent_path)
      by_ring_key.emplace_back(ringKeyDistance(database[query], database[i]), i);
  if (by_ring_key.empty()) return std::nullopt;
  const std::size_t keep = std::min(by_ring_key.size(), static_cast<std::size_t>(ring_key_candidates));
  std::partial_sort(by_ring_key.begin(), by_ring_key.begin() + static_cast<std::ptrdiff_t>(keep), by_ring_key.end());
  LoopCandidate best;
  for (std::size_t k = 0; k < keep; ++k) {
    const auto [ring_distance, i] = by_ring_key[k];
    const ScanContextMatch match = compareScanContexts(database[query], database[i]);
    if (best.index < 0 || match.distance < best.match.distance) {
      best.index = static_cast<int>(i);
      best.ring_key_distance = ring_distance;
      best.match = match;
    }
  }
  return best;
}

}  // namespace lvslam::loop
