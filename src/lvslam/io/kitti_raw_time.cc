#include "lvslam/io/kitti_raw_time.h"

#include <cstdio>
#include <fstream>

#include "lvslam/core/error.h"

namespace lvslam {

namespace {

// Days from 1970-01-01 to a proleptic Gregorian date (H. Hinnant's days_from_civil).
long long daysFromCivil(long long y, unsigned m, unsigned d) {
  y -= m <= 2;
  const long long era = (y >= 0 ? y : y - 399) / 400;
  const unsigned yoe = static_cast<unsigned>(y - era * 400);
  const unsigned doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
  const unsigned doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
  return era * 146097 + static_cast<long long>(doe) - 719468;
}

}  // namespace

std::optional<double> parseKittiTimestamp(const std::string& text) {
  int year = 0, month = 0, day = 0, hour = 0, minute = 0, second = 0, consumed = 0;
  if (std::sscanf(text.c_str(), "%4d-%2d-%2d %2d:%2d:%2d%n", &year, &month, &day, &hour, &minute, &second,
                  &consumed) != 6)
    return std::nullopt;
  if (month < 1 || month > 12 || day < 1 || day > 31 || hour > 23 || minute > 59 || second > 60 || hour < 0 ||
      minute < 0 || second < 0)
    return std::nullopt;
  // The fraction digit by digit: no locale, no rounding through a float parse.
  double fraction = 0.0, scale = 0.1;
  std::size_t i = static_cast<std::size_t>(consumed);
  if (i < text.size() && text[i] == '.') {
    for (++i; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i, scale *= 0.1) fraction += (text[i] - '0') * scale;
  }
  for (; i < text.size(); ++i)
    if (text[i] != ' ' && text[i] != '\r' && text[i] != '\t') return std::nullopt;
  const long long days = daysFromCivil(year, static_cast<unsigned>(month), static_cast<unsigned>(day));
  return static_cast<double>(days * 86400 + hour * 3600 + minute * 60 + second) + fraction;
}

std::vector<double> readKittiTimestamps(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path, "cannot open time stamp file");
  std::vector<double> times;
  std::string line;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const auto t = parseKittiTimestamp(line);
    if (!t) throw Error(path + ":" + std::to_string(line_no), "expected a time stamp like '2011-09-26 13:02:25.964389445'");
    times.push_back(*t);
  }
  return times;
}

}  // namespace lvslam
