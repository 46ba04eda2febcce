#pragma once
// How an evaluation is shown: a short human summary, or one JSON object
// {"pairs", "align", "scale", "ate", "rpe", "kitti", "aligned_mean_translation_error"}.
#include <string>

#include "lvslam/eval/evaluate.h"

namespace lvslam::eval {

// Several lines, each ending in '\n'.
std::string formatSummary(const EvalResult& result);

// One line, no trailing newline. Statistics without data are null.
std::string formatJson(const EvalResult& result);

}  // namespace lvslam::eval
