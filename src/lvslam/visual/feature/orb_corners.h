#pragma once
// The measures ORB puts on a FAST corner (Rublee et al. 2011), written out so
// that each runs only where it is needed: the Harris measure ranks every FAST
// corner, the orientation is computed only for the corners the grid keeps
// (cv::ORB orients every candidate, most of which the grid then drops).
#include <opencv2/core.hpp>

namespace lvslam::visual {

// Harris & Stephens' det(M) - 0.04 trace(M)^2, M summed over the 7x7 window
// of 3x3 Sobel gradients centred on (x, y), as ORB ranks corners; scaled as
// cv::cornerHarris(7, 3, 0.04) scales it. (x, y) must lie at least 4 pixels
// inside the 8-bit image.
float harrisResponse(const cv::Mat& image, int x, int y);

// ORB's orientation: the angle in degrees, in [0, 360) and image axes (y down),
// from (x, y) to the intensity centroid of the disc of the given radius around
// it. (x, y) must lie at least radius (<= 50) pixels inside the 8-bit image.
float intensityCentroidAngle(const cv::Mat& image, int x, int y, int radius);

}  // namespace lvslam::visual
