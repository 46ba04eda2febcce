#include "lvslam/eval/association.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam::eval {

namespace {

// A candidate match from a stamp of the shorter trajectory.
struct Candidate {
  std::size_t short_index;
  std::size_t long_index;
  double dt;
};

void checkIncreasing(const Trajectory& traj, const char* name) {
  for (std::size_t i = 1; i < traj.size(); ++i)
    if (!(traj[i].t > traj[i - 1].t))
      throw Error(fmt::format("{} trajectory, pose {}", name, i),
                  "time stamps must increase strictly for association");
}

// Index of the nearest stamp; on a tie the earlier one, like numpy's argmin.
std::size_t nearestIndex(const Trajectory& traj, double t) {
  const auto it = std::lower_bound(traj.begin(), traj.end(), t,
                                   [](const StampedPose& p, double value) { return p.t < value; });
  if (it == traj.begin()) return 0;
  const std::size_t after = static_cast<std::size_t>(it - traj.begin());
  if (after == traj.size()) return after - 1;
  return std::abs(traj[after - 1].t - t) <= std::abs(traj[after].t - t) ? after - 1 : after;
}

// evo's matching_time_indices: for each stamp of the short trajectory its
// nearest stamp in the long one, kept when within max_dt.
std::vector<Candidate> nearestCandidates(const Trajectory& shorter, const Trajectory& longer,
                                         double max_dt) {
  std::vector<Candidate> candidates;
  for (std::size_t i = 0; i < shorter.size(); ++i) {
    const std::size_t j = nearestIndex(longer, shorter[i].t);
    const double dt = std::abs(longer[j].t - shorter[i].t);
    if (dt <= max_dt) candidates.push_back({i, j, dt});
  }
  return candidates;
}

// Where evo would use a long-trajectory pose twice, the closer match keeps it
// and the other stamp stays unmatched (closest first, earlier on ties).
std::vector<Candidate> makeOneToOne(std::vector<Candidate> candidates, std::size_t long_size) {
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const Candidate& a, const Candidate& b) { return a.dt < b.dt; });
  std::vector<bool> used(long_size, false);
  std::vector<Candidate> kept;
  for (const Candidate& c : candidates) {
    if (used[c.long_index]) continue;
    used[c.long_index] = true;
    kept.push_back(c);
  }
  std::sort(kept.begin(), kept.end(),
            [](const Candidate& a, const Candidate& b) { return a.short_index < b.short_index; });
  return kept;
}

}  // namespace

std::vector<IndexPair> associateByTime(const Trajectory& gt, const Trajectory& est, double max_dt) {
  checkIncreasing(gt, "ground-truth");
  checkIncreasing(est, "estimated");
  if (gt.empty() || est.empty()) return {};
  // evo searches from the shorter trajectory into the longer one; with equal
  // lengths the estimate (its second trajectory) is the one searched from.
  const bool est_longer = est.size() > gt.size();
  const Trajectory& shorter = est_longer ? gt : est;
  const Trajectory& longer = est_longer ? est : gt;
  const auto kept = makeOneToOne(nearestCandidates(shorter, longer, max_dt), longer.size());
  std::vector<IndexPair> pairs;
  pairs.reserve(kept.size());
  for (const Candidate& c : kept)
    pairs.push_back(est_longer ? IndexPair{c.short_index, c.long_index}
                               : IndexPair{c.long_index, c.short_index});
  return pairs;
}

AssociatedPoses selectPairs(const Trajectory& gt, const Trajectory& est,
                            const std::vector<IndexPair>& pairs) {
  AssociatedPoses poses;
  poses.gt.reserve(pairs.size());
  poses.est.reserve(pairs.size());
  for (const IndexPair& p : pairs) {
    poses.gt.push_back(gt.at(p.gt_index).T_world_frame);
    poses.est.push_back(est.at(p.est_index).T_world_frame);
  }
  return poses;
}

}  // namespace lvslam::eval
