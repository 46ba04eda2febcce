#pragma once
// Returns from a surface nearly parallel to the beam. At grazing incidence
// consecutive returns of a ring land far apart and recede along the beam,
// and what is left of such a wall are columns of the scan pattern that look
// like vertical lines and move with the sensor. LOAM (Zhang & Singh 2014,
// Sec. V-A) takes no features there. Here a return is grazing when neither
// neighbour of its ring (in azimuth) lies within the radius its shape is
// judged in, and its range lies between theirs (the surface recedes through
// it); a thin object in front of the background (nearer than both) stays.
#include <vector>

#include "lvslam/lidar/deskew.h"

namespace lvslam::lidar {

// One flag per point. Points without a ring (ring < 0) are never grazing.
std::vector<bool> grazingReturns(const std::vector<TimedPoint>& points, double radius);

}  // namespace lvslam::lidar
