// Runs the real binary: bad input must give exit code 2 and exactly one
// stderr line that names the file, line or key at fault; never a crash.
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "apps/run_lvslam.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::TempDir;

using testing::lines;
using testing::RunResult;
using testing::runLvslam;

TEST(Cli, HelpSucceeds) {
  TempDir dir;
  const RunResult r = runLvslam(dir, "--help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* sub : {"run", "eval", "simulate", "convert"}) EXPECT_NE(r.out.find(sub), std::string::npos) << sub;
}

TEST(Cli, UnknownSubcommandIsAUsageError) {
  TempDir dir;
  EXPECT_EQ(runLvslam(dir, "frobnicate").exit_code, 2);
}

TEST(Cli, MissingTrajectoryFileIsOneLineNamingIt) {
  TempDir dir;
  dir.write("est.txt", "0 0 0 0 0 0 0 1\n");
  const RunResult r = runLvslam(dir, "eval --gt nowhere.txt --est est.txt");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("nowhere.txt"), std::string::npos) << r.err;
}

TEST(Cli, BadTrajectoryLineNamesFileAndLine) {
  TempDir dir;
  dir.write("gt.txt", "0 0 0 0 0 0 0 1\n1 1 0 0 0 0 0 1\n2 2 0 x 0 0 0 1\n");
  dir.write("est.txt", "0 0 0 0 0 0 0 1\n");
  const RunResult r = runLvslam(dir, "eval --gt gt.txt --est est.txt");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("gt.txt:3"), std::string::npos) << r.err;
}

TEST(Cli, MalformedSequenceYamlNamesTheFile) {
  TempDir dir;
  dir.write("seq/sequence.yaml", "format: lvslam-sequence/1\nlidar: {point_fields: [x, y\n");
  const RunResult r = runLvslam(dir, "run --sequence seq --out out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("sequence.yaml"), std::string::npos) << r.err;
}

TEST(Cli, ScanOfTheWrongSizeNamesTheScanFile) {
  TempDir dir;
  dir.write("seq/sequence.yaml", "format: lvslam-sequence/1\nlidar:\n  point_fields: [x, y, z, intensity]\n");
  dir.write("seq/lidar/times.txt", "0.0 000000.bin\n");
  dir.write("seq/lidar/000000.bin", std::string(4 * 4 * 10 + 3, '\x01'));
  const RunResult r = runLvslam(dir, "run --sequence seq --mode lidar --out out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("000000.bin"), std::string::npos) << r.err;
}

// Exit code 2 and one stderr line holding `text`.
void expectOneLineError(const RunResult& r, const std::string& text) {
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
}

// A LiDAR-only sequence of one scan of ten points: enough to reach the options' checks.
void writeOneScanSequence(TempDir& dir) {
  dir.write("seq/sequence.yaml", "format: lvslam-sequence/1\nlidar:\n  point_fields: [x, y, z, intensity]\n");
  dir.write("seq/lidar/times.txt", "0.0 000000.bin\n");
  dir.write("seq/lidar/000000.bin", std::string(4 * 4 * 10, '\0'));
}

TEST(Cli, AMapInThatIsNotAMapIsOneLineNamingIt) {
  TempDir dir;
  writeOneScanSequence(dir);
  dir.write("room.lvmap", "ply\nformat ascii 1.0\n");
  expectOneLineError(runLvslam(dir, "run --sequence seq --mode lidar --out out --map-in room.lvmap"),
                     "room.lvmap: not an lvslam map");
}

TEST(Cli, AMapOutWithoutLoopClosureOrNowhereToWriteIsOneLineBeforeTheRun) {
  TempDir dir;
  writeOneScanSequence(dir);
  dir.write("no_loops.yaml", "loop:\n  enabled: false\n");
  expectOneLineError(
      runLvslam(dir, "run --sequence seq --mode lidar --out out --config no_loops.yaml --map-out m.lvmap"),
      "--map-out: a saved map is the loop closure's keyframes: it needs loop.enabled: true");
  expectOneLineError(runLvslam(dir, "run --sequence seq --mode lidar --out out --map-out missing/m.lvmap"),
                     "missing/m.lvmap: cannot write the map here");
}

TEST(Cli, UnsortedTimesNameTheLine) {
  TempDir dir;
  dir.write("seq/sequence.yaml", "format: lvslam-sequence/1\nlidar:\n  point_fields: [x, y, z]\n");
  dir.write("seq/lidar/times.txt", "1.0 a.bin\n0.5 b.bin\n");
  dir.write("seq/lidar/a.bin", std::string(12, '\0'));
  dir.write("seq/lidar/b.bin", std::string(12, '\0'));
  const RunResult r = runLvslam(dir, "run --sequence seq --out out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("times.txt:2"), std::string::npos) << r.err;
}

TEST(Cli, BadSimulateOptionNamesTheOption) {
  TempDir dir;
  const RunResult r = runLvslam(dir, "simulate --scenario moon --out s");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("scenario"), std::string::npos) << r.err;
}

TEST(Cli, AllNanScansAreSurvivedAndReported) {
  // A LiDAR-only sequence whose scans hold only NaN points: a documented
  // recovery (the odometry reports lost), not a crash.
  TempDir dir;
  dir.write("seq/sequence.yaml", "format: lvslam-sequence/1\nlidar:\n  point_fields: [x, y, z]\n");
  const float nan = std::nanf("");
  std::string record(12, '\0');
  for (int i = 0; i < 3; ++i) std::memcpy(&record[4 * i], &nan, 4);
  std::string scan;
  for (int i = 0; i < 100; ++i) scan += record;
  dir.write("seq/lidar/a.bin", scan);
  dir.write("seq/lidar/b.bin", scan);
  dir.write("seq/lidar/times.txt", "0.0 a.bin\n0.1 b.bin\n");
  const RunResult r = runLvslam(dir, "run --sequence seq --out out");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("lost"), std::string::npos) << r.out;
}

// A report needs the run's stats.json whole: a missing or truncated one is one
// line naming it, exit 2, and no page.
TEST(Cli, ReportOfAFolderWithoutStatsNamesStatsJson) {
  TempDir dir;
  dir.write("run/trajectory.tum", "0 0 0 0 0 0 0 1\n");
  const RunResult r = runLvslam(dir, "report run");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("stats.json"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "run" / "report.html"));
}

TEST(Cli, ReportOfATruncatedStatsJsonNamesItAndTheByte) {
  TempDir dir;
  dir.write("run/trajectory.tum", "0 0 0 0 0 0 0 1\n");
  dir.write("run/stats.json", "{\"summary\": {\"mode\": \"lidar\", \"images\": 0},\n\"frames\": [\n  {\"t\": 0.1, \"so");
  const RunResult r = runLvslam(dir, "report run");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("stats.json"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("truncated"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "run" / "report.html"));
}

// A straight line along x with a gentle curve: enough path for RPE at 1 m.
std::string tumPath(double offset_y) {
  std::string text;
  for (int i = 0; i < 60; ++i)
    text += std::to_string(0.1 * i) + " " + std::to_string(0.1 * i) + " " + std::to_string(offset_y + 0.002 * i * i) +
            " 0 0 0 0 1\n";
  return text;
}

TEST(Cli, ReportOfARunFolderHoldsItsData) {
  TempDir dir;
  dir.write("run/stats.json",
            "{\"summary\": {\"mode\": \"lidar\", \"images\": 0, \"scans\": 1, \"switches\": 0},\n"
            "\"switches\": [], \"frames\": [], \"scans\": [{\"t\": 0.0, \"status\": \"tracking\", \"features\": 7}]}\n");
  dir.write("run/trajectory.tum", tumPath(0.25));
  dir.write("run/groundtruth.tum", tumPath(0.0));
  const RunResult r = runLvslam(dir, "report run");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(dir.file("run/report.html"));
  const std::string html{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(html.find("\"kind\": \"run\""), std::string::npos);
  EXPECT_NE(html.find("\"status\": \"tracking\""), std::string::npos) << "stats.json inlined";
  EXPECT_NE(html.find("\"name\": \"ATE (se3 aligned)\""), std::string::npos);
  EXPECT_NE(html.find("\"p\": [0,0.25,0,0.1,0.25"), std::string::npos) << "the trajectory as written";
  EXPECT_EQ(html.find("src=\"http"), std::string::npos) << "nothing loaded from the network";
}

TEST(Cli, EvalReportHoldsBothTrajectoriesAndTheirErrors) {
  TempDir dir;
  dir.write("gt.txt", tumPath(0.0));
  dir.write("est.txt", tumPath(0.5));
  const RunResult r = runLvslam(dir, "eval --gt gt.txt --est est.txt --report page.html");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(dir.file("page.html"));
  const std::string html{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  EXPECT_NE(html.find("\"kind\": \"eval\""), std::string::npos);
  EXPECT_NE(html.find("\"name\": \"gt.txt\""), std::string::npos);
  EXPECT_NE(html.find("\"name\": \"est.txt\""), std::string::npos);
  EXPECT_NE(html.find("\"name\": \"RPE 1 m, translation\""), std::string::npos);
  // The estimate is the ground truth moved by 0.5 m: aligned, its ATE is zero.
  const std::size_t at = html.find("\"ATE (se3 aligned)\"");
  ASSERT_NE(at, std::string::npos);
  const std::string series = html.substr(at, 4000);
  std::smatch ate;
  ASSERT_TRUE(std::regex_search(series, ate, std::regex(R"("stats": \{"count": 60, "rmse": ([-0-9.e]+),)"))) << series;
  EXPECT_LT(std::stod(ate[1]), 1e-9);
}

TEST(Cli, EvalReportOfTrajectoriesThatDoNotMeetIsOneLine) {
  TempDir dir;
  dir.write("gt.txt", tumPath(0.0));
  dir.write("est.txt", "100 0 0 0 0 0 0 1\n101 1 0 0 0 0 0 1\n");
  const RunResult r = runLvslam(dir, "eval --gt gt.txt --est est.txt --report page.html");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(lines(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("gt.txt"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "page.html"));
}

// Without the JavaScript assets a run still succeeds and says, in one line,
// that report.html was not written and how to install them.
TEST(Cli, RunWithoutReportAssetsWarnsInOneLine) {
  TempDir dir;
  dir.write("seq/sequence.yaml", "format: lvslam-sequence/1\nlidar:\n  point_fields: [x, y, z]\n");
  dir.write("seq/lidar/a.bin", std::string(12 * 10, '\0'));
  dir.write("seq/lidar/b.bin", std::string(12 * 10, '\0'));
  dir.write("seq/lidar/times.txt", "0.0 a.bin\n0.1 b.bin\n");
  dir.write("out/report.html", "an earlier run's page");
  ::setenv("LVSLAM_REPORT_ASSETS", dir.file("nowhere").c_str(), 1);
  const RunResult r = runLvslam(dir, "run --sequence seq --out out");
  ::unsetenv("LVSLAM_REPORT_ASSETS");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  const std::regex warning(R"((^|\n)warning: out/report.html not written: .*nowhere.*install-deps.sh[^\n]*\n)");
  EXPECT_TRUE(std::regex_search(r.err, warning)) << r.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "out" / "report.html"));
}

TEST(Cli, BenchFamiliesOptionsAreCheckedBeforeAnyRun) {
  TempDir dir;
  const RunResult unknown = runLvslam(dir, "bench --suite families --families room,moon --no-doc");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--families"), std::string::npos) << unknown.err;
  const RunResult classic = runLvslam(dir, "bench --quick --no-doc --work-dir work");
  EXPECT_EQ(classic.exit_code, 2);
  EXPECT_EQ(lines(classic.err), 1) << classic.err;
  EXPECT_NE(classic.err.find("--quick"), std::string::npos) << classic.err;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "work")) << "nothing simulated";
}

// The families suite's quick form end to end on one short family (about 10 s
// on 2 cores): the summary row names the family and has numbers, and the
// document gets the tables while its hand-written text stays.
TEST(Cli, BenchFamiliesQuickRunsOneFamilyEndToEnd) {
  TempDir dir;
  dir.write("bench.md", "# Benchmarks\n\nhand-written\n");
  const RunResult r = runLvslam(dir, std::string("bench --suite families --families room --quick --duration 3 "
                                                 "--no-ablations --work-dir work --doc bench.md --config '") +
                                         LVSLAM_SOURCE_DIR + "/config/sim.yaml'");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::regex summary(R"(\| room \| neither \| 0\.\d{4} \| (0\.\d{4}|x) \| 0\.\d{4} \| 0\.\d{4} \| )"
                           R"((yes|no), \d+\.\d % (below|above) (lidar|visual) \|)");
  EXPECT_TRUE(std::regex_search(r.out, summary)) << r.out;
  EXPECT_NE(r.out.find("#### room: both sensors good"), std::string::npos) << r.out;
  const std::regex seed_row(R"(\| 1 \| 0\.\d{4} / 0\.\d{4} \| .* \| 0\.\d{4} / 0\.\d{4}, \d+ % \|)");
  EXPECT_TRUE(std::regex_search(r.out, seed_row)) << r.out;
  std::ifstream doc(dir.file("bench.md"));
  const std::string text{std::istreambuf_iterator<char>(doc), std::istreambuf_iterator<char>()};
  EXPECT_EQ(text.rfind("# Benchmarks\n\nhand-written\n", 0), 0u) << text;
  EXPECT_NE(text.find("#### room: both sensors good"), std::string::npos) << text;
  std::ifstream page(dir.file("bench.html"));  // beside the document
  const std::string html{std::istreambuf_iterator<char>(page), std::istreambuf_iterator<char>()};
  EXPECT_NE(html.find("\"name\": \"room: both sensors good\""), std::string::npos);
  EXPECT_NE(html.find("\"columns\": [\"lidar\",\"visual\",\"fused\"]"), std::string::npos) << html.substr(0, 300);
}

}  // namespace
}  // namespace lvslam
