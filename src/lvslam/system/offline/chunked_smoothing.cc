#include "lvslam/system/offline/chunked_smoothing.h"

#include <algorithm>
#include <map>

#include "lvslam/core/error.h"

namespace lvslam::system {

namespace {

// Nodes [begin, end) free (unless fixed), every other node a factor of
// theirs reaches held; solved, and the free ones written back.
void solveChunk(std::vector<PoseNode>& nodes, const std::vector<PoseFactor>& factors,
                const std::vector<std::vector<int>>& factors_at, int begin, int end,
                const PoseGraphSolveConfig& solve) {
  std::map<int, int> local;
  std::vector<PoseNode> chunk;
  const auto localIndex = [&](int node) {
    const auto [it, inserted] = local.try_emplace(node, static_cast<int>(chunk.size()));
    if (inserted) {
      const PoseNode& held = nodes[static_cast<std::size_t>(node)];
      chunk.push_back({held.T_world_camera, held.fixed || node < begin || node >= end});
    }
    return it->second;
  };
  std::vector<int> used;
  for (int node = begin; node < end; ++node) {
    localIndex(node);
    for (const int f : factors_at[static_cast<std::size_t>(node)]) used.push_back(f);
  }
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<PoseFactor> local_factors;
  local_factors.reserve(used.size());
  for (const int f : used) {
    PoseFactor factor = factors[static_cast<std::size_t>(f)];
    factor.from = localIndex(factor.from);
    factor.to = localIndex(factor.to);
    local_factors.push_back(std::move(factor));
  }
  // A chunk that reaches no held node is held by its first node, as a whole graph is.
  if (!solvePoseGraph(chunk, local_factors, solve)) return;
  for (const auto& [node, index] : local)
    if (node >= begin && node < end) nodes[static_cast<std::size_t>(node)] = chunk[static_cast<std::size_t>(index)];
}

}  // namespace

void smoothInChunks(std::vector<PoseNode>& nodes, const std::vector<PoseFactor>& factors,
                    const ChunkedSmoothingConfig& config) {
  if (config.chunk_nodes <= config.overlap_nodes || config.overlap_nodes < 0 || config.sweeps < 1)
    throw Error("smoothInChunks", "needs chunk_nodes > overlap_nodes >= 0 and sweeps >= 1");
  const int n = static_cast<int>(nodes.size());
  if (n <= config.chunk_nodes) {
    solvePoseGraph(nodes, factors, config.solve);
    return;
  }
  std::vector<std::vector<int>> factors_at(nodes.size());
  for (std::size_t f = 0; f < factors.size(); ++f) {
    factors_at[static_cast<std::size_t>(factors[f].from)].push_back(static_cast<int>(f));
    factors_at[static_cast<std::size_t>(factors[f].to)].push_back(static_cast<int>(f));
  }
  const int step = config.chunk_nodes - config.overlap_nodes;
  std::vector<int> begins;
  for (int begin = 0;; begin += step) {
    begins.push_back(begin);
    if (begin + config.chunk_nodes >= n) break;
  }
  for (int sweep = 0; sweep < config.sweeps; ++sweep) {
    const bool forward = sweep % 2 == 0;
    for (std::size_t i = 0; i < begins.size(); ++i) {
      const int begin = begins[forward ? i : begins.size() - 1 - i];
      solveChunk(nodes, factors, factors_at, begin, std::min(n, begin + config.chunk_nodes), config.solve);
    }
  }
}

}  // namespace lvslam::system
