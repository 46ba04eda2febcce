#pragma once
// The loop candidate of a keyframe by Scan Context (Kim & Kim, IROS 2018):
// the older keyframes nearest by ring key, outside the recent path, then the
// one of those with the smallest column-shift-invariant distance.
#include <optional>
#include <vector>

#include "lvslam/loop/scan_context.h"

namespace lvslam::loop {

struct LoopCandidate {
  int index = -1;                  // into the database
  double ring_key_distance = 0.0;
  ScanContextMatch match;
};

// database[i] with path_lengths[i]; the query is the last entry. The
// `ring_key_candidates` keyframes nearest by ring key that lie at least
// `exclude_recent_path` metres of path behind the query, compared whole,
// best (smallest descriptor distance) first.
std::vector<LoopCandidate> findLoopCandidates(const std::vector<ScanContext>& database,
                                              const std::vector<double>& path_lengths, double exclude_recent_path,
                                              int ring_key_candidates);

// The best of them; none when no keyframe lies far enough behind.
std::optional<LoopCandidate> findLoopCandidate(const std::vector<ScanContext>& database,
                                               const std::vector<double>& path_lengths, double exclude_recent_path,
                                               int ring_key_candidates);

}  // namespace lvslam::loop
