#include "lvslam/io/intrinsics_check.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

namespace lvslam {

namespace {

constexpr double kMinFovDeg = 1.0, kMaxFovDeg = 179.0;

double fieldOfViewDeg(double pixels, double focal) { return 2.0 * std::atan(pixels / (2.0 * focal)) * 180.0 / std::numbers::pi; }

void checkFocal(const char* name, double focal, int pixels, const char* side, const std::string& yaml_path,
                std::vector<std::string>& warnings) {
  const double fov = focal > 0.0 ? fieldOfViewDeg(pixels, focal) : 180.0;
  if (fov >= kMinFovDeg && fov <= kMaxFovDeg) return;
  warnings.push_back(fmt::format("{}: key 'camera.intrinsics': {} = {:g} gives the {}-pixel image {} a field of view "
                                 "of {:.3g} deg; implausible (expected {:g} to {:g} deg)",
                                 yaml_path, name, focal, pixels, side, fov, kMinFovDeg, kMaxFovDeg));
}

}  // namespace

std::vector<std::string> intrinsicsWarnings(const PinholeCamera& camera, const std::string& yaml_path) {
  std::vector<std::string> warnings;
  checkFocal("fx", camera.fx(), camera.width(), "width", yaml_path, warnings);
  checkFocal("fy", camera.fy(), camera.height(), "height", yaml_path, warnings);
  if (camera.cx() < 0.0 || camera.cx() > camera.width() || camera.cy() < 0.0 || camera.cy() > camera.height())
    warnings.push_back(fmt::format("{}: key 'camera.intrinsics': principal point ({:g}, {:g}) lies outside the "
                                   "{}x{} image; implausible",
                                   yaml_path, camera.cx(), camera.cy(), camera.width(), camera.height()));
  return warnings;
}

}  // namespace lvslam
