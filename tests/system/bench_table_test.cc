// The paper-style bench tables: cell rules (x above half lost, n/a without
// ground truth, fail), the families suite's tables and verdict, and the
// marked section of docs/benchmarks.md.
#include "lvslam/system/bench_table.h"

#include <gtest/gtest.h>

namespace lvslam::system {
namespace {

BenchCell cell(std::optional<double> ate, double lost) {
  BenchCell c;
  c.ate_mean_m = ate;
  c.lost_fraction = lost;
  c.real_time_factor = 2.5;
  c.online_real_time_factor = 3.0;
  c.peak_rss_mib = 140.4;
  return c;
}

TEST(BenchTable, CellsFollowThePapersMarks) {
  EXPECT_EQ(accuracyCellText(cell(0.01234, 0.0)), "0.0123");
  EXPECT_EQ(accuracyCellText(cell(0.01234, 0.5)), "0.0123");  // exactly half is not "more than half"
  EXPECT_EQ(accuracyCellText(cell(0.01234, 0.51)), "x");
  EXPECT_EQ(accuracyCellText(cell(std::nullopt, 0.0)), "n/a");
  BenchCell failed = cell(0.01, 0.0);
  failed.failure = "lvslam: error: ...";
  EXPECT_EQ(accuracyCellText(failed), "fail");
  EXPECT_EQ(accuracyCellText(std::nullopt), "");
}

TEST(BenchTable, MeanRowAveragesEachColumnOverTheSeeds) {
  BenchCell slow = cell(0.03, 0.1);
  slow.real_time_factor = 1.5;
  slow.online_real_time_factor = 2.0;
  slow.peak_rss_mib = 200.0;
  BenchCell failed = cell(0.01, 0.0);
  failed.failure = "lvslam: error: ...";
  const std::vector<BenchRow> rows = {
      {"room", {{"lidar", cell(0.01, 0.0)}, {"fused", cell(0.05, 0.0)}, {"visual", cell(0.02, 0.0)}}},
      {"room-seed2", {{"lidar", slow}, {"fused", cell(0.04, 0.6)}, {"visual", failed}, {"extra", cell(0.1, 0.0)}}}};
  const BenchRow mean = meanRow(rows, {"lidar", "visual", "fused", "extra"}, "mean");
  EXPECT_EQ(mean.sequence, "mean");
  ASSERT_TRUE(mean.cells.count("lidar"));
  EXPECT_NEAR(*mean.cells.at("lidar").ate_mean_m, 0.02, 1e-12);
  EXPECT_NEAR(mean.cells.at("lidar").real_time_factor, 2.0, 1e-12);
  EXPECT_NEAR(mean.cells.at("lidar").online_real_time_factor, 2.5, 1e-12);
  EXPECT_DOUBLE_EQ(mean.cells.at("lidar").peak_rss_mib, 200.0);
  EXPECT_EQ(accuracyCellText(mean.cells.at("fused")), "x");  // one seed lost more than half
  EXPECT_EQ(accuracyCellText(mean.cells.at("visual")), "fail");
  EXPECT_EQ(mean.cells.count("extra"), 0u);  // not run on every seed
}

TEST(BenchTable, TablesHaveOneRowPerSequenceAndOneColumnPerMode) {
  std::vector<BenchRow> rows = {{"room", {{"lidar", cell(0.0105, 0.0)}, {"fused", cell(0.0094, 0.0)}}},
                                {"gate-night", {{"lidar", cell(0.02, 0.0)}, {"visual", cell(std::nullopt, 0.9)}}}};
  const std::vector<std::string> columns = {"lidar", "visual", "fused"};
  EXPECT_EQ(accuracyTable(rows, columns),
            "| sequence | lidar | visual | fused |\n|---|---:|---:|---:|\n"
            "| room | 0.0105 |  | 0.0094 |\n| gate-night | 0.0200 | x |  |\n");
  const std::string speed = speedTable(rows, columns);
  EXPECT_NE(speed.find("| room | 3.00x / 2.50x, 140 MiB |  | 3.00x / 2.50x, 140 MiB |"), std::string::npos) << speed;
}

// A families-suite cell: online and refined ATE rmse, vision share, latency.
BenchCell familyCell(std::optional<double> online, std::optional<double> refined, std::optional<double> vision) {
  BenchCell c = cell(std::nullopt, 0.0);
  c.ate_rmse_m = online;
  c.refined_ate_rmse_m = refined;
  c.vision_share = vision;
  c.latency_median_ms = 132.96;
  return c;
}

BenchCell failedCell() {
  BenchCell c = familyCell(0.01, 0.01, 0.5);
  c.failure = "lvslam: error: ...";
  return c;
}

TEST(BenchTable, FamilyCellsShowOnlineAndRefinedAteAndTheVisionShare) {
  EXPECT_EQ(familyAccuracyCellText(familyCell(0.01234, 0.00987, std::nullopt)), "0.0123 / 0.0099");
  EXPECT_EQ(familyAccuracyCellText(familyCell(0.01234, 0.00987, 0.627)), "0.0123 / 0.0099, 63 %");
  EXPECT_EQ(familyAccuracyCellText(familyCell(0.01234, std::nullopt, 1.0)), "0.0123 / n/a, 100 %");
  EXPECT_EQ(familyAccuracyCellText(failedCell()), "fail");
  BenchCell lost = familyCell(0.5, 0.4, 0.3);
  lost.lost_fraction = 0.7;
  EXPECT_EQ(familyAccuracyCellText(lost), "x");
  EXPECT_EQ(familyAccuracyCellText(std::nullopt), "");
}

TEST(BenchTable, FamilyTablesHaveOneRowPerSeed) {
  BenchCell no_latency = familyCell(0.0105, 0.0098, std::nullopt);
  no_latency.latency_median_ms.reset();
  const std::vector<BenchRow> rows = {
      {"1", {{"lidar", familyCell(0.0105, 0.0098, std::nullopt)}, {"fused", familyCell(0.0094, std::nullopt, 0.63)}}},
      {"2", {{"lidar", no_latency}, {"fused", failedCell()}}}};
  const std::vector<std::string> columns = {"lidar", "fused"};
  EXPECT_EQ(familyAccuracyTable(rows, columns),
            "| seed | lidar | fused |\n|---|---:|---:|\n"
            "| 1 | 0.0105 / 0.0098 | 0.0094 / n/a, 63 % |\n| 2 | 0.0105 / 0.0098 | fail |\n");
  EXPECT_EQ(familySpeedTable(rows, columns),
            "| seed | lidar | fused |\n|---|---:|---:|\n"
            "| 1 | 3.00x / 2.50x, 133 ms, 140 MiB | 3.00x / 2.50x, 133 ms, 140 MiB |\n| 2 | 3.00x / 2.50x, n/a, 140 MiB | fail |\n");
}

TEST(BenchTable, MeanRowAveragesTheFamilyFigures) {
  BenchCell slow = familyCell(0.03, std::nullopt, 0.8);
  slow.latency_median_ms = 200.0;
  const std::vector<BenchRow> rows = {{"1", {{"fused", familyCell(0.01, 0.008, 0.6)}}}, {"2", {{"fused", slow}}}};
  const BenchCell mean = meanRow(rows, {"fused"}, "mean").cells.at("fused");
  EXPECT_NEAR(*mean.ate_rmse_m, 0.02, 1e-12);
  EXPECT_FALSE(mean.refined_ate_rmse_m);  // seed 2 has none: no mean of one seed under the others' name
  EXPECT_NEAR(*mean.vision_share, 0.7, 1e-12);
  EXPECT_NEAR(*mean.latency_median_ms, (132.96 + 200.0) / 2.0, 1e-12);
  EXPECT_EQ(familyAccuracyCellText(mean), "0.0200 / n/a, 70 %");
}

BenchRow modes(std::optional<BenchCell> lidar, std::optional<BenchCell> visual, std::optional<BenchCell> fused) {
  BenchRow row{"mean", {}};
  if (lidar) row.cells["lidar"] = *lidar;
  if (visual) row.cells["visual"] = *visual;
  if (fused) row.cells["fused"] = *fused;
  return row;
}

TEST(BenchTable, VerdictComparesFusedWithTheBetterSingleMode) {
  // Visual is the better single mode (0.02 < 0.05); fused 0.015 is 25 % below it.
  const FusionVerdict better = fusionVerdict(modes(familyCell(0.05, 0.04, std::nullopt), familyCell(0.02, 0.02, 0.9),
                                                   familyCell(0.015, 0.01, 0.7)));
  EXPECT_TRUE(better.fused_beats);
  EXPECT_EQ(better.better_single, "visual");
  EXPECT_NEAR(*better.gain_percent, 25.0, 1e-9);
  EXPECT_EQ(better.text, "yes, 25.0 % below visual");
  // LiDAR better (0.01); fused 0.0125 is 25 % above it (the refined 0.005 does not count).
  const FusionVerdict worse = fusionVerdict(modes(familyCell(0.01, 0.01, std::nullopt), familyCell(0.02, 0.02, 0.9),
                                                  familyCell(0.0125, 0.005, 0.7)));
  EXPECT_FALSE(worse.fused_beats);
  EXPECT_EQ(worse.better_single, "lidar");
  EXPECT_NEAR(*worse.gain_percent, -25.0, 1e-9);
  EXPECT_EQ(worse.text, "no, 25.0 % above lidar");
}

TEST(BenchTable, VerdictSkipsSingleModesThatFailOrLoseTrack) {
  BenchCell lost = familyCell(0.001, 0.001, 0.2);
  lost.lost_fraction = 0.8;
  // Visual lost more than half: its tiny ATE is no contender; LiDAR 0.04 is.
  const FusionVerdict v = fusionVerdict(modes(familyCell(0.04, 0.04, std::nullopt), lost, familyCell(0.03, 0.03, 0.5)));
  EXPECT_EQ(v.text, "yes, 25.0 % below lidar");
  EXPECT_EQ(fusionVerdict(modes(failedCell(), lost, familyCell(0.03, 0.03, 0.5))).text,
            "yes (neither single mode tracks)");
  EXPECT_EQ(fusionVerdict(modes(familyCell(0.04, 0.04, std::nullopt), lost, failedCell())).text, "no (fused fail)");
  EXPECT_EQ(fusionVerdict(modes(familyCell(0.04, 0.04, std::nullopt), lost, lost)).text, "no (fused x)");
  EXPECT_EQ(fusionVerdict(modes(familyCell(0.04, 0.04, std::nullopt), lost, std::nullopt)).text,
            "no (fused not run)");
  EXPECT_EQ(fusionVerdict(modes(familyCell(0.04, 0.04, std::nullopt), lost, familyCell(std::nullopt, 0.03, 0.5))).text,
            "no (fused n/a)");
}

TEST(BenchTable, SummaryHasOneRowPerFamily) {
  const std::vector<FamilySummary> families = {
      {"corridor", "LiDAR",
       modes(familyCell(0.20, 0.15, std::nullopt), familyCell(0.10, 0.09, 0.95), familyCell(0.08, std::nullopt, 0.9)),
       {}},
      {"night", "camera", modes(familyCell(0.01, 0.01, std::nullopt), failedCell(), familyCell(0.011, 0.009, 0.1)),
       {}}};
  EXPECT_EQ(familySummaryTable(families),
            "| family | weaker sensor | lidar | visual | fused | fused, refined "
            "| fused beats the better single mode |\n|---|---|---:|---:|---:|---:|---|\n"
            "| corridor | LiDAR | 0.2000 | 0.1000 | 0.0800 | n/a | yes, 20.0 % below visual |\n"
            "| night | camera | 0.0100 | fail | 0.0110 | 0.0090 | no, 10.0 % above lidar |\n");
}

TEST(BenchTable, SummaryOverSeedsJudgesTheMeanAndCountsTheSeedsFusedWins) {
  const std::vector<BenchRow> seeds = {
      modes(familyCell(0.010, 0.01, std::nullopt), familyCell(0.02, 0.02, 0.9), familyCell(0.006, 0.005, 0.8)),
      modes(familyCell(0.010, 0.01, std::nullopt), familyCell(0.02, 0.02, 0.9), familyCell(0.012, 0.010, 0.8))};
  const std::vector<std::string> columns = {"lidar", "visual", "fused"};
  const BenchRow mean = meanRow(seeds, columns, "mean");  // fused 0.009 against lidar 0.010
  const std::string table = familySummaryTable({{"gate", "neither", mean, seeds}});
  EXPECT_NE(table.find("| gate | neither | 0.0100 | 0.0200 | 0.0090 | 0.0075 "
                       "| yes, 10.0 % below lidar; 1 of 2 seeds |"),
            std::string::npos)
      << table;
}

TEST(BenchTable, MarkedSectionIsReplacedInPlaceOrAppended) {
  const std::string begin = kBenchBeginMarker, end = kBenchEndMarker;
  const std::string doc = "# Benchmarks\n\nhand-written\n\n" + begin + "\nold table\n" + end + "\n\n## Later\ntext\n";
  const std::string replaced = replaceMarkedSection(doc, "new table\n");
  EXPECT_EQ(replaced, "# Benchmarks\n\nhand-written\n\n" + begin + "\nnew table\n" + end + "\n\n## Later\ntext\n");
  EXPECT_EQ(replaceMarkedSection(replaced, "new table\n"), replaced);  // idempotent
  const std::string appended = replaceMarkedSection("# Benchmarks\nhand-written", "t\n");
  EXPECT_EQ(appended, "# Benchmarks\nhand-written\n\n" + begin + "\nt\n" + end + "\n");
}

}  // namespace
}  // namespace lvslam::system
