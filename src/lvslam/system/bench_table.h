#pragma once
// The paper-style tables of `lvslam bench` (Cao et al., Tables I and II:
// aligned mean translation error per sequence and method, x for a run that
// loses track for more than half of its frames), with real-time factor and
// peak memory, as Markdown for the terminal and docs/benchmarks.md.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lvslam::system {

struct BenchCell {
  std::optional<double> ate_mean_m;  // none: no ground truth (or too few poses)
  double lost_fraction = 0.0;
  double real_time_factor = 0.0;
  double peak_rss_mib = 0.0;
  std::string failure;  // the run did not finish: its error line
};

struct BenchRow {
  std::string sequence;
  std::map<std::string, BenchCell> cells;  // by column (mode or ablation)
};

// "0.0105" (metres), "x" (lost more than half), "n/a" (no ground truth),
// "fail" (the run stopped with an error), "" (not run).
std::string accuracyCellText(const std::optional<BenchCell>& cell);

// One row of per-column means over `rows` (the seeds of the simulated
// suite): ATE and real-time factor averaged, peak memory and lost fraction
// the largest (so a column where one row lost more than half shows x, one
// where a row failed shows fail, one where a row has no ATE shows n/a); a
// column that some row lacks is left out.
BenchRow meanRow(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns, const std::string& label);

std::string accuracyTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns);
std::string speedTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns);

// `document` with the text between the two marker lines replaced by
// `section` (markers appended at the end when absent).
std::string replaceMarkedSection(const std::string& document, const std::string& section);
inline constexpr const char* kBenchBeginMarker = "<!-- lvslam bench: begin (generated, do not edit) -->";
inline constexpr const char* kBenchEndMarker = "<!-- lvslam bench: end -->";

}  // namespace lvslam::system
