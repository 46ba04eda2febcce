#pragma once
// The paper-style tables of `lvslam bench` (Cao et al., Tables I and II:
// aligned mean translation error per sequence and method, x for a run that
// loses track for more than half of its frames), with real-time factor and
// peak memory, as Markdown for the terminal and docs/benchmarks.md; and the
// tables of the scenario families suite, which judge fusion per family.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace lvslam::system {

struct BenchCell {
  std::optional<double> ate_mean_m;  // none: no ground truth (or too few poses)
  double lost_fraction = 0.0;
  double real_time_factor = 0.0;         // the whole run
  double online_real_time_factor = 0.0;  // the online pipeline alone
  double peak_rss_mib = 0.0;
  std::string failure;  // the run did not finish: its error line
  // The families suite's figures (stats.json summary):
  std::optional<double> ate_rmse_m;          // online trajectory (accuracy.ate.rmse)
  std::optional<double> refined_ate_rmse_m;  // offline refinement (accuracy_refined.ate.rmse)
  std::optional<double> vision_share;        // visual_output_frames / images; none without vision
  std::optional<double> latency_median_ms;
};

struct BenchRow {
  std::string sequence;
  std::map<std::string, BenchCell> cells;  // by column (mode or ablation)
};

// "0.0105" (metres), "x" (lost more than half), "n/a" (no ground truth),
// "fail" (the run stopped with an error), "" (not run).
std::string accuracyCellText(const std::optional<BenchCell>& cell);

// One row of per-column means over `rows` (the seeds of the simulated
// suite): ATE, real-time factor, vision share and latency averaged (an
// optional figure only when every row has it), peak memory and lost fraction
// the largest (so a column where one row lost more than half shows x, one
// where a row failed shows fail, one where a row has no ATE shows n/a); a
// column that some row lacks is left out.
BenchRow meanRow(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns, const std::string& label);

std::string accuracyTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns);
std::string speedTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns);

// The families suite (`lvslam bench --suite families`): rows are the seeds
// of one family, the columns its modes.
//
// "0.0105 / 0.0098, 63 %": ATE rmse (m) of the online and of the refined
// trajectory, then the share of frames whose pose vision entered (when the
// mode has vision); "n/a" for a missing figure, x and fail as above.
std::string familyAccuracyCellText(const std::optional<BenchCell>& cell);
std::string familyAccuracyTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns);
// "2.09x, 133 ms, 106 MiB": real-time factor, median latency, peak memory.
std::string familySpeedTable(const std::vector<BenchRow>& rows, const std::vector<std::string>& columns);

// Whether online fused beats the better single mode of `row` (columns
// "lidar", "visual", "fused"; online ATE rmse). A single mode that failed, lost
// more than half its frames or has no ATE is no contender.
struct FusionVerdict {
  bool fused_beats = false;
  std::string better_single;          // "lidar", "visual" or "" (neither usable)
  std::optional<double> gain_percent;  // (single - fused) / single * 100; < 0: fused is worse
  std::string text;                    // "yes, 14.3 % below lidar", "no, 8.0 % above visual", "no (fused fail)"
};
FusionVerdict fusionVerdict(const BenchRow& row);

struct FamilySummary {
  std::string family;
  std::string weaker_sensor;  // the family's intended weaker sensor, as the table shows it
  BenchRow row;               // the mean over the seeds, or the one seed
  std::vector<BenchRow> seed_rows;  // with more than one, the verdict says on how many seeds fused wins
};
// One row per family: weaker sensor, online ATE of lidar, visual and fused,
// the refined fused ATE, and the verdict of `row` ("yes, 14.3 % below lidar;
// 2 of 3 seeds": one fused run is one draw, the mean can hide a split).
std::string familySummaryTable(const std::vector<FamilySummary>& families);

// `document` with the text between the two marker lines replaced by
// `section` (markers appended at the end when absent).
std::string replaceMarkedSection(const std::string& document, const std::string& section);
inline constexpr const char* kBenchBeginMarker = "<!-- lvslam bench: begin (generated, do not edit) -->";
inline constexpr const char* kBenchEndMarker = "<!-- lvslam bench: end -->";

}  // namespace lvslam::system
