#pragma once
// JSON arrays of numbers at a fixed precision: the report carries thousands
// of poses and points, and millimetres are all a plot can show, so digits
// past the precision are size without information.
#include <string>
#include <vector>

namespace lvslam::report {

// "[1.25,-0.5,null]": `decimals` places, trailing zeros dropped, NaN and
// infinity as null.
std::string fixedArray(const std::vector<double>& values, int decimals);

}  // namespace lvslam::report
