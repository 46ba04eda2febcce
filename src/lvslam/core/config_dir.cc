#include "lvslam/core/config_dir.h"

namespace lvslam {

std::string configDir() { return LVSLAM_CONFIG_DIR; }

}  // namespace lvslam
