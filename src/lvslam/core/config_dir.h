#pragma once
// config/ of the source tree this binary was built from: the sensor presets
// and advanced.yaml (every key of the configuration with its default). It is
// found from the build tree and from any clone built where it lies.
#include <string>

namespace lvslam {

std::string configDir();

}  // namespace lvslam
