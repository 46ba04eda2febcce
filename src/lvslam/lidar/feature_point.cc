#include "lvslam/lidar/feature_point.h"

namespace lvslam::lidar {

std::string_view className(FeatureClass c) {
  switch (c) {
    case FeatureClass::kGround: return "ground";
    case FeatureClass::kFacade: return "facade";
    case FeatureClass::kRoof: return "roof";
    case FeatureClass::kPillar: return "pillar";
    case FeatureClass::kBeam: return "beam";
    case FeatureClass::kVertex: return "vertex";
  }
  return "unknown";
}

}  // namespace lvslam::lidar
