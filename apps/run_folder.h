#pragma once
// The end of a run, shared by `lvslam run` (cmd_run.cc) and lvslam_node
// (ros/): the run folder's files (stats.json, trajectory_refined.tum,
// map.ply, lines.ply, subsystems/, groundtruth.tum, report.html), the summary
// on stdout, and the faults that end the command. trajectory.tum itself is
// streamed by the caller while the run goes (TumStream).
#include <string>

#include "lvslam/io/recording.h"
#include "lvslam/system/run_recording.h"

namespace lvslam::apps {

// Throws the recording's input fault (after writing what came before it), or
// std::runtime_error "no result: ..." when the run gave no pose (then nothing
// is written and the streamed trajectory.tum is removed). The run's records
// and the recording's ground truth are let go once written, before the
// report (which reads the folder): on a long run they are most of the memory.
void finishRunFolder(const std::string& out_dir, Recording& recording, system::RunResult run, const std::string& mode,
                     bool deterministic);

}  // namespace lvslam::apps
