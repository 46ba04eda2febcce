#include "lvslam/system/offline/chunked_smoothing.h"

#include <algorithm>

#include "lvslam/core/error.h"

namespace lvslam::system {

namespace {

// Nodes [begin, end) free (unless fixed), every other node a factor of
// theirs reaches held; a chunk that reaches no held node is held by its
// first node, as a whole graph is.
void solveChunk(std::vector<PoseNode>& nodes, const RecordFile<PoseFactor>& factors,
                const std::vector<std::vector<int>>& factors_at, int begin, int end,
                const PoseGraphSolveConfig& solve) {
  std::vector<int> used;
  for (int node = begin; node < end; ++node)
    for (const int f : factors_at[static_cast<std::size_t>(node)]) used.push_back(f);
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  std::vector<PoseFactor> chunk_factors;
  chunk_factors.reserve(used.size());
  for (const int f : used) chunk_factors.push_back(factors[static_cast<std::size_t>(f)]);
  std::vector<const PoseFactor*> chunk;
  chunk.reserve(used.size());
  for (const PoseFactor& factor : chunk_factors) chunk.push_back(&factor);
  solveSubgraph(begin, end, chunk, [&nodes](int id) -> PoseNode& { return nodes[static_cast<std::size_t>(id)]; },
                solve);
}

}  // namespace

void smoothInChunks(std::vector<PoseNode>& nodes, const RecordFile<PoseFactor>& factors,
                    const ChunkedSmoothingConfig& config) {
  if (config.chunk_nodes <= config.overlap_nodes || config.overlap_nodes < 0 || config.sweeps < 1)
    throw Error("smoothInChunks", "needs chunk_nodes > overlap_nodes >= 0 and sweeps >= 1");
  const int n = static_cast<int>(nodes.size());
  if (n <= config.chunk_nodes) {
    solvePoseGraph(nodes, std::vector<PoseFactor>(factors.begin(), factors.end()), config.solve);
    return;
  }
  std::vector<std::vector<int>> factors_at(nodes.size());
  int f = 0;
  for (const PoseFactor& factor : factors) {
    factors_at[static_cast<std::size_t>(factor.from)].push_back(f);
    factors_at[static_cast<std::size_t>(factor.to)].push_back(f);
    ++f;
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
