// stats_frames.jsonl: each frame's online record on its own line, on disk as
// soon as it is added (a killed run keeps it), read back as JSON.
#include <sstream>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "lvslam/system/frame_stats_stream.h"
#include "support/temp_dir.h"

namespace lvslam::system {
namespace {

using testing::slurpBinary;
using testing::TempDir;

FrameOutput gatedFrame() {
  FrameOutput f;
  f.t = 1700000000.125;
  f.T_world_camera = Eigen::Isometry3d::Identity();
  f.source = OutputSource::kVisual;
  f.fused = true;
  f.gated.push_back({f.t, FactorSource::kVisual, 40.5, 16.27, "jump of \"9 cm\"\nin one frame"});
  f.gated.push_back({f.t, FactorSource::kLidar, 30.0, 16.27, "second"});
  f.latency_ms = 12.5;
  return f;
}

TEST(FrameStatsStream, EachFrameIsOneJsonLineOnDiskAsSoonAsItIsAdded) {
  TempDir dir;
  FrameStatsStream stream(dir.file("stats_frames.jsonl"), true);
  FrameOutput first;
  first.t = 1700000000.0;
  first.problem = "not tracking";
  stream.add(first);
  EXPECT_EQ(slurpBinary(dir.file("stats_frames.jsonl")), onlineFrameJson(first, true).str() + "\n");
  stream.add(gatedFrame());
  std::istringstream lines(slurpBinary(dir.file("stats_frames.jsonl")));
  std::string line;
  ASSERT_TRUE(std::getline(lines, line));
  EXPECT_EQ(nlohmann::json::parse(line)["problem"], "not tracking");
  EXPECT_EQ(nlohmann::json::parse(line)["pose"], false);
  ASSERT_TRUE(std::getline(lines, line));
  const nlohmann::json second = nlohmann::json::parse(line);
  EXPECT_EQ(second["t"].get<double>(), 1700000000.125);
  EXPECT_EQ(second["source"], "visual");
  ASSERT_EQ(second["gated"].size(), 2u);
  EXPECT_EQ(second["gated"][0]["reason"], "jump of \"9 cm\"\nin one frame");
  EXPECT_EQ(second["latency_ms"].get<double>(), 12.5);
  EXPECT_FALSE(std::getline(lines, line));
}

TEST(FrameStatsStream, WithoutTimingsNoLatencyIsWritten) {
  EXPECT_EQ(onlineFrameJson(gatedFrame(), false).str().find("latency"), std::string::npos);
}

TEST(FrameStatsStream, AnUnwritablePathIsNamed) {
  TempDir dir;
  const std::string path = dir.file("missing/stats_frames.jsonl");
  EXPECT_NE(testing::errorMessageOf([&] { FrameStatsStream stream(path, true); }).find(path), std::string::npos);
}

}  // namespace
}  // namespace lvslam::system
