#pragma once
// Time stamps are double seconds everywhere (small or Unix times); doubles
// keep microseconds for Unix times up to year 2255.
#include <string>

namespace lvslam {

// Formats a time stamp with nanosecond digits, e.g. "1628249320.123456000",
// so simulated times survive a write-read round trip exactly enough.
std::string formatTimestamp(double t);

// Parses a decimal time stamp; false when the text is not a finite number.
bool parseTimestamp(const std::string& text, double& t);

}  // namespace lvslam
