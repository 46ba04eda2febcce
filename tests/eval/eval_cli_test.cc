// `lvslam eval` end to end through its CLI function, and the report format.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "command.h"
#include "eval/eval_test_trajectories.h"
#include "lvslam/core/error.h"
#include "lvslam/eval/eval_report.h"
#include "lvslam/eval/json_writer.h"
#include "lvslam/io/tum.h"

namespace lvslam::eval {
namespace {

class EvalCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(::testing::TempDir()) /
           ("lvslam_eval_cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  void writeText(const std::string& name, const std::string& text) const {
    std::ofstream(path(name)) << text;
  }

  // Parses and runs `lvslam eval ARGS`; returns the exit code, stdout in out.
  int run(std::vector<std::string> args, std::string* out = nullptr) const {
    CLI::App app;
    apps::CommandAction action;
    apps::addEvalCommand(app, action);
    args.insert(args.begin(), "eval");
    std::reverse(args.begin(), args.end());  // CLI11 takes a reversed vector
    app.parse(args);
    ::testing::internal::CaptureStdout();
    int code = -1;
    try {
      code = action();
    } catch (...) {
      ::testing::internal::GetCapturedStdout();
      throw;
    }
    const std::string captured = ::testing::internal::GetCapturedStdout();
    if (out) *out = captured;
    return code;
  }

  std::filesystem::path dir_;
};

TEST_F(EvalCli, JsonIsOneObjectWithTheReportedFields) {
  const Trajectory gt = testing::makeSpiral(200);
  writeTum(path("gt.txt"), gt);
  writeTum(path("est.txt"), gt);
  std::string out;
  ASSERT_EQ(run({"--gt", path("gt.txt"), "--est", path("est.txt"), "--json"}, &out), 0);
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.front(), '{');
  EXPECT_EQ(out.find('\n'), out.size() - 1);  // one line
  for (const char* key : {"\"pairs\": 200", "\"scale\": 1", "\"ate\": {\"rmse\": ", "\"rpe\": {\"delta_m\": 10",
                          "\"rot_deg\": {", "\"kitti\": {", "\"aligned_mean_translation_error\": "})
    EXPECT_NE(out.find(key), std::string::npos) << key << " missing in " << out;
}

TEST_F(EvalCli, SummaryNamesTheAlignedMeanTranslationError) {
  const Trajectory gt = testing::makeSpiral(50);
  writeTum(path("gt.txt"), gt);
  writeTum(path("est.txt"), gt);
  std::string out;
  ASSERT_EQ(run({"--gt", path("gt.txt"), "--est", path("est.txt"), "--align", "sim3"}, &out), 0);
  EXPECT_NE(out.find("aligned mean translation error: 0.000000 m"), std::string::npos) << out;
  EXPECT_NE(out.find("alignment: sim3"), std::string::npos) << out;
}

TEST_F(EvalCli, BadLineIsAnErrorNamingFileAndLine) {
  writeTum(path("gt.txt"), testing::makeSpiral(10));
  writeText("est.txt", "0 1 2 3 0 0 0 1\n0.1 1 2 oops 0 0 0 1\n");
  try {
    run({"--gt", path("gt.txt"), "--est", path("est.txt")});
    FAIL() << "expected lvslam::Error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), path("est.txt") + ":2");
  }
}

TEST_F(EvalCli, MissingFileIsAnError) {
  writeTum(path("gt.txt"), testing::makeSpiral(10));
  EXPECT_THROW(run({"--gt", path("gt.txt"), "--est", path("nope.txt")}), Error);
}

TEST_F(EvalCli, TooFewAssociatedPairsIsAnErrorNamingBothFiles) {
  Trajectory est = testing::makeSpiral(10);
  for (StampedPose& p : est) p.t += 100.0;  // another clock
  writeTum(path("gt.txt"), testing::makeSpiral(10));
  writeTum(path("est.txt"), est);
  try {
    run({"--gt", path("gt.txt"), "--est", path("est.txt")});
    FAIL() << "expected lvslam::Error";
  } catch (const Error& e) {
    EXPECT_NE(e.where().find(path("gt.txt")), std::string::npos) << e.what();
    EXPECT_NE(e.where().find(path("est.txt")), std::string::npos) << e.what();
  }
}

TEST_F(EvalCli, DegenerateAlignmentIsAnError) {
  Trajectory est = testing::makeSpiral(10);
  for (StampedPose& p : est) p.T_world_frame.translation().setZero();
  writeTum(path("gt.txt"), testing::makeSpiral(10));
  writeTum(path("est.txt"), est);
  EXPECT_THROW(run({"--gt", path("gt.txt"), "--est", path("est.txt")}), Error);
}

TEST_F(EvalCli, UnknownAlignmentIsAUsageError) {
  EXPECT_THROW(run({"--gt", "a", "--est", "b", "--align", "affine"}), CLI::ParseError);
}

TEST(EvalReport, JsonCarriesTheAteMeanUnderThePaperName) {
  const Trajectory gt = testing::makeSpiral(100);
  Trajectory est = gt;
  for (std::size_t k = 0; k < est.size(); k += 7) est[k].T_world_frame.translation().x() += 0.25;
  const EvalResult r = evaluate(gt, est);
  const std::string json = formatJson(r);
  EXPECT_NE(json.find("\"aligned_mean_translation_error\": " + jsonNumber(r.ate.stats.mean)), std::string::npos);
  EXPECT_NE(json.find("\"ate\": {\"rmse\": " + jsonNumber(r.ate.stats.rmse)), std::string::npos);
  EXPECT_EQ(jsonNumber(r.ate.stats.mean).find('e'), std::string::npos);
}

TEST(JsonWriter, EscapesStringsAndWritesNonFiniteAsNull) {
  EXPECT_EQ(jsonString("a\"b\\c\n\x01"), "\"a\\\"b\\\\c\\n\\u0001\"");
  EXPECT_EQ(jsonNumber(std::numeric_limits<double>::quiet_NaN()), "null");
  EXPECT_EQ(jsonNumber(1.3034497), "1.3034497");
  EXPECT_EQ(std::stod(jsonNumber(0.1 + 0.2)), 0.1 + 0.2);  // round-trips exactly
  EXPECT_EQ(JsonObject().addCount("n", 3).addRaw("x", "null").str(), "{\"n\": 3, \"x\": null}");
}

}  // namespace
}  // namespace lvslam::eval
