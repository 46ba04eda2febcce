#pragma once
// One run of the system over a recording, as `lvslam run` and `lvslam bench`
// do it: the pipeline, the assembled output, the summary and, when the
// recording has ground truth, the accuracy (in the frame the ground truth
// gives; SE3 alignment when the scale is metric, Sim3 otherwise).
#include <optional>

#include "lvslam/eval/evaluate.h"
#include "lvslam/io/recording.h"
#include "lvslam/system/output_assembly.h"
#include "lvslam/system/run_report.h"
#include "lvslam/system/system_pipeline.h"

namespace lvslam::system {

struct RunResult {
  PipelineRecords records;
  SystemOutput output;
  RunSummary summary;
  std::optional<eval::EvalResult> accuracy;          // of the online trajectory
  std::optional<eval::EvalResult> accuracy_refined;  // of the offline refinement
};

RunResult runRecording(Recording& recording, const SystemConfig& config, const ProgressCallback& progress = {},
                       const FrameOutputCallback& on_frame = {});

// The accuracy of one of an output's trajectories (its online or its
// refined one) against the recording's ground truth; none without ground
// truth or with too few poses to align.
std::optional<eval::EvalResult> evaluateOutput(const Recording& recording, const SystemOutput& output,
                                               const Trajectory& trajectory);

}  // namespace lvslam::system
