#pragma once
// The two sensors' clocks checked against each other. A gap in one stream
// is a drop-out when the other stream is still there where the gap ends (it
// went on at its own pace); when the stream resumes beyond the other's whole
// span (after its end, or the stream lay before the other's start until the
// gap), one clock jumped: the stamps cannot be merged, and treating it as a
// drop-out would join poses across the jump.
#include <string>
#include <vector>

#include "lvslam/io/times_file.h"

namespace lvslam {

// Throws lvslam::Error("<a_path>:<line>", "time stamp jumps by ... s ...")
// at the first frame of `a` after such a jump; nothing when either stream has
// fewer than three frames. `factor` times the median period makes a gap, as
// in findTimeJumps.
void checkClocksAgree(const std::vector<TimedFile>& a, const std::string& a_path, const std::vector<TimedFile>& b,
                      const std::string& b_path, double factor = 5.0);

}  // namespace lvslam
