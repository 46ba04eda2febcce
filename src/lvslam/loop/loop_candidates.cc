#include "lvslam/loop/loop_candidates.h"

#include <algorithm>
#include <utility>

namespace lvslam::loop {

std::vector<LoopCandidate> findLoopCandidates(const std::vector<ScanContext>& database,
                                              const std::vector<double>& path_lengths, double exclude_recent_path,
                                              int ring_key_candidates) {
  if (database.size() < 2) return {};
  const std::size_t query = database.size() - 1;
  std::vector<std::pair<double, std::size_t>> by_ring_key;
  for (std::size_t i = 0; i < query; ++i)
    if (path_lengths[query] - path_lengths[i] >= exclude_recent_path)
      by_ring_key.emplace_back(ringKeyDistance(database[query], database[i]), i);
  const std::size_t keep = std::min(by_ring_key.size(), static_cast<std::size_t>(std::max(0, ring_key_candidates)));
  std::partial_sort(by_ring_key.begin(), by_ring_key.begin() + static_cast<std::ptrdiff_t>(keep), by_ring_key.end());
  std::vector<LoopCandidate> candidates;
  for (std::size_t k = 0; k < keep; ++k) {
    const auto [ring_distance, i] = by_ring_key[k];
    candidates.push_back({static_cast<int>(i), ring_distance, compareScanContexts(database[query], database[i])});
  }
  // Stable: equal distances keep the ring key's order, as the first best did.
  std::stable_sort(candidates.begin(), candidates.end(), [](const LoopCandidate& a, const LoopCandidate& b) {
    return a.match.distance < b.match.distance;
  });
  return candidates;
}

std::optional<LoopCandidate> findLoopCandidate(const std::vector<ScanContext>& database,
                                               const std::vector<double>& path_lengths, double exclude_recent_path,
                                               int ring_key_candidates) {
  const std::vector<LoopCandidate> candidates =
      findLoopCandidates(database, path_lengths, exclude_recent_path, ring_key_candidates);
  if (candidates.empty()) return std::nullopt;
  return candidates.front();
}

}  // namespace lvslam::loop
