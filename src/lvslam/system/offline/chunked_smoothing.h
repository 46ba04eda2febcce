#pragma once
// The whole run's pose graph smoothed one overlapping chunk of nodes at a
// time, so that the solver's memory is that of one chunk whatever the
// run's length. Block Gauss-Seidel over the nodes in creation order: each
// chunk's nodes free, the nodes its factors reach outside it held at their
// latest estimates; a forward sweep, then a backward one, so that what a
// late part of the run knows reaches the early part. It gives the whole
// graph's solution when a measurement moves the poses within much less
// than a chunk, as in the estimator's graph (every factor spans a few
// frames); a tie across many chunks (a loop) would need many sweeps: loop
// corrections are applied apart (loop_correction.h).
#include <vector>

#include "lvslam/system/online/pose_graph.h"
#include "lvslam/system/record_file.h"

namespace lvslam::system {

struct ChunkedSmoothingConfig {
  int chunk_nodes = 6000;    // free nodes per solve (about 2000 camera frames in fused mode)
  int overlap_nodes = 1500;  // shared by consecutive chunks
  int sweeps = 2;            // forward, backward, forward ...
  PoseGraphSolveConfig solve{3.0, 50, true};
};

// Optimises the free nodes in place; the factors are read from disk a
// chunk at a time (record_file.h). A graph of at most chunk_nodes nodes is
// solved whole, as solvePoseGraph does.
void smoothInChunks(std::vector<PoseNode>& nodes, const RecordFile<PoseFactor>& factors,
                    const ChunkedSmoothingConfig& config);

}  // namespace lvslam::system
