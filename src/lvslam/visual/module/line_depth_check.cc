#include "lvslam/visual/module/line_depth_check.h"

#include <algorithm>
#include <cmath>

namespace lvslam::visual {

std::vector<LineDepth> lineDepths(const VisualMap& map, int keyframe) {
  std::vector<LineDepth> out;
  const Keyframe& k = map.keyframe(keyframe);
  for (const int id : k.line_landmark) {
    if (id < 0) continue;
    const LineLandmark& l = map.line(id);
    const double z = (k.T_camera_world * (0.5 * (l.start_world + l.end_world))).z();
    if (z > 0.0 && std::isfinite(z)) out.push_back({id, z});
  }
  return out;
}

std::vector<int> removeLineDepthOutliers(VisualMap& map, int keyframe, const std::vector<LineDepth>& before,
                                         const LineDepthCheckConfig& config) {
  std::vector<int> removed;
  if (!map.hasKeyframe(keyframe)) return removed;
  std::vector<LineDepth> pairs;  // line, change ratio after / before
  for (const LineDepth& after : lineDepths(map, keyframe)) {
    const auto it = std::find_if(before.begin(), before.end(), [&](const LineDepth& b) { return b.line == after.line; });
    if (it != before.end()) pairs.push_back({after.line, after.depth / it->depth});
  }
  if (pairs.size() < 3) return removed;  // no scene median to compare with
  std::vector<double> ratios;
  for (const LineDepth& p : pairs) ratios.push_back(p.depth);
  std::nth_element(ratios.begin(), ratios.begin() + ratios.size() / 2, ratios.end());
  const double median = ratios[ratios.size() / 2];
  for (const LineDepth& p : pairs) {
    const double limit = map.line(p.line).from_fusion ? config.fusion_ratio : config.ratio;
    if (std::abs(p.depth - median) > limit) {
      map.removeLine(p.line);
      removed.push_back(p.line);
    }
  }
  return removed;
}

}  // namespace lvslam::visual
