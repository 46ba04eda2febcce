#include "lvslam/io/times_file.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/core/file_access.h"
#include "lvslam/core/timestamp.h"

namespace lvslam {

std::vector<TimedFile> readTimesFile(const std::string& path) {
  std::ifstream in = openInputFile(path);
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::vector<TimedFile> files;
  std::string line;
  for (int line_no = 1; std::getline(in, line); ++line_no) {
    const std::string where = path + ":" + std::to_string(line_no);
    std::istringstream ss(line);
    std::string stamp, file, extra;
    if (!(ss >> stamp) || stamp[0] == '#') continue;  // blank line or comment
    double t = 0.0;
    if (!parseTimestamp(stamp, t)) throw Error(where, "malformed time stamp '" + stamp + "'");
    if (!(ss >> file)) throw Error(where, "expected '<timestamp> <file>'");
    if (ss >> extra) throw Error(where, "unexpected text after the file name: '" + extra + "'");
    if (!files.empty() && !(t > files.back().t))
      throw Error(where, fmt::format("time stamp {} is not after the previous one ({}): times must increase",
                                     formatTimestamp(t), formatTimestamp(files.back().t)));
    const std::filesystem::path full = folder / file;
    if (fileKind(full.string(), where) != FileKind::kRegular)
      throw Error(where, "file '" + full.string() + "' not found");
    files.push_back({t, full.string(), line_no});
  }
  return files;
}

double medianPeriod(const std::vector<TimedFile>& files) {
  if (files.size() < 2) return 0.0;
  std::vector<double> periods;
  for (std::size_t i = 1; i < files.size(); ++i) periods.push_back(files[i].t - files[i - 1].t);
  std::nth_element(periods.begin(), periods.begin() + periods.size() / 2, periods.end());
  return periods[periods.size() / 2];
}

std::vector<std::size_t> findTimeJumps(const std::vector<TimedFile>& files, double factor) {
  std::vector<std::size_t> jumps;
  if (files.size() < 3) return jumps;
  const double median = medianPeriod(files);
  for (std::size_t i = 1; i < files.size(); ++i)
    if (files[i].t - files[i - 1].t > factor * median) jumps.push_back(i);
  return jumps;
}

}  // namespace lvslam
