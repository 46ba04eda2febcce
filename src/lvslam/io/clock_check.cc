#include "lvslam/io/clock_check.h"

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/core/timestamp.h"

namespace lvslam {

namespace {

void checkOneWay(const std::vector<TimedFile>& a, const std::string& a_path, const std::vector<TimedFile>& b,
                 const std::string& b_path, double factor) {
  // The other stream's span, widened by what counts as a gap in it.
  const double tolerance = factor * medianPeriod(b);
  const double b_first = b.front().t - tolerance, b_last = b.back().t + tolerance;
  for (const std::size_t i : findTimeJumps(a, factor)) {
    const TimedFile& before = a[i - 1];
    const TimedFile& after = a[i];
    const bool leaves_after_end = before.t <= b_last && after.t > b_last;
    const bool enters_after_start = before.t < b_first && after.t >= b_first;
    if (!leaves_after_end && !enters_after_start) continue;  // a drop-out: the other stream is there
    throw Error(fmt::format("{}:{}", a_path, after.line),
                fmt::format("time stamp {} jumps by {:.3f} s after the previous one ({}), beyond the {} of {} "
                            "({}): one sensor's clock jumped, not a drop-out",
                            formatTimestamp(after.t), after.t - before.t, formatTimestamp(before.t),
                            leaves_after_end ? "last stamp" : "first stamp", b_path,
                            formatTimestamp(leaves_after_end ? b.back().t : b.front().t)));
  }
}

}  // namespace

void checkClocksAgree(const std::vector<TimedFile>& a, const std::string& a_path, const std::vector<TimedFile>& b,
                      const std::string& b_path, double factor) {
  if (a.size() < 3 || b.size() < 3) return;
  checkOneWay(a, a_path, b, b_path, factor);
  checkOneWay(b, b_path, a, a_path, factor);
}

}  // namespace lvslam
