// The paper-style bench tables: cell rules (x above half lost, n/a without
// ground truth, fail) and the marked section of docs/benchmarks.md.
#include "lvslam/system/bench_table.h"

#include <gtest/gtest.h>

namespace lvslam::system {
namespace {

BenchCell cell(std::optional<double> ate, double lost) {
  BenchCell c;
  c.ate_mean_m = ate;
  c.lost_fraction = lost;
  c.real_time_factor = 2.5;
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
  EXPECT_NE(speed.find("| room | 2.50x, 140 MiB |  | 2.50x, 140 MiB |"), std::string::npos) << speed;
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
