#pragma once
// Intrinsics that read but cannot be the camera's: fx = 1e-9 or 1e300 pass
// every parser and make the visual subsystem quietly useless. A focal length
// is judged by the field of view it gives the image (1 to 179 degrees), the
// principal point by lying inside the image.
#include <string>
#include <vector>

#include "lvslam/core/camera.h"

namespace lvslam {

// One warning per implausible value, naming `yaml_path` and the key; none
// when all is well.
std::vector<std::string> intrinsicsWarnings(const PinholeCamera& camera, const std::string& yaml_path);

}  // namespace lvslam
