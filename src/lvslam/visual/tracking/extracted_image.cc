#include "lvslam/visual/tracking/extracted_image.h"

namespace lvslam::visual {

ExtractedImage extractImage(FeatureExtractor& extractor, const ImageFrame& frame) {
  ExtractedImage out;
  out.timestamp = frame.timestamp;
  out.stats = imageStatistics(frame.image);
  out.features = extractor.extract(frame);
  out.features.timestamp = frame.timestamp;
  return out;
}

}  // namespace lvslam::visual
