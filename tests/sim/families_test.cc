#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "lvslam/core/error.h"
#include "lvslam/sim/families.h"
#include "lvslam/sim/simulate_sequence.h"
#include "support/temp_dir.h"

namespace lvslam::sim {
namespace {

namespace fs = std::filesystem;
using lvslam::testing::errorMessageOf;

std::map<std::string, std::string> folderBytes(const fs::path& root) {
  std::map<std::string, std::string> contents;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (!entry.is_regular_file()) continue;
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    contents[fs::relative(entry.path(), root).string()] = ss.str();
  }
  return contents;
}

class Families : public ::testing::TestWithParam<std::string> {};

// Same seed, same bytes (a short stretch of each family).
TEST_P(Families, GenerateDeterministically) {
  SimOptions options = familyOptions(GetParam());
  EXPECT_EQ(options.family, GetParam());
  EXPECT_EQ(options.duration, 60.0);
  options.duration = 0.35;
  testing::TempDir a, b;
  const SimulationSummary summary = simulateSequence(options, a.path().string());
  simulateSequence(options, b.path().string());
  EXPECT_EQ(summary.images, 6);
  EXPECT_EQ(summary.scans, 2);
  const auto bytes = folderBytes(a.path());
  EXPECT_TRUE(bytes == folderBytes(b.path()));
  const YAML::Node yaml = YAML::Load(bytes.at("sequence.yaml"));
  EXPECT_EQ(yaml["name"].as<std::string>(), "sim_" + GetParam() + "_seed1");
  EXPECT_EQ(yaml["lidar"]["rings"].as<int>(), GetParam() == "hall16" ? 16 : 32);
  EXPECT_EQ(static_cast<bool>(yaml["camera"]["distortion"]), options.distortion);
}

INSTANTIATE_TEST_SUITE_P(All, Families, ::testing::ValuesIn(familyNames()));

TEST(FamilyOptions, ListsEveryFamilyOfTheIssueAndNamesBadOnes) {
  for (const char* name : {"corridor", "hall16", "glass", "yard", "crowd", "dropout", "night", "blur", "plain",
                           "blackout", "room", "gate"})
    EXPECT_NO_THROW(validate(familyOptions(name))) << name;
  EXPECT_EQ(familyNames().size(), 12u);
  EXPECT_NE(errorMessageOf([] { familyOptions("kitchen"); }).find("--family"), std::string::npos);
  // The distortion is on by default in at least one family; room and gate are the scenarios as they were.
  EXPECT_TRUE(familyOptions("yard").distortion);
  SimOptions room = familyOptions("room");
  room.family.clear();
  EXPECT_EQ(room.scenario, "room");
  EXPECT_FALSE(room.beam_footprint || room.auto_exposure || room.rolling_shutter || room.people > 0);
  EXPECT_EQ(familyOptions("blackout").camera_blackout->end - familyOptions("blackout").camera_blackout->begin, 6.0);
  EXPECT_EQ(familyOptions("crowd").people, 12);
  EXPECT_EQ(familyOptions("dropout").lidar_dropout->end - familyOptions("dropout").lidar_dropout->begin, 2.0);
}

}  // namespace
}  // namespace lvslam::sim
