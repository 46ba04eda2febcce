#include <cmath>

#include <gtest/gtest.h>

#include "lvslam/core/error.h"
#include "lvslam/sim/scenario.h"
#include "lvslam/sim/sim_options.h"
#include "support/temp_dir.h"

namespace lvslam::sim {
namespace {

using lvslam::testing::errorMessageOf;

TEST(SimOptions, UnknownScenarioNamesTheOption) {
  SimOptions options;
  options.scenario = "kitchen";
  EXPECT_THROW(validate(options), Error);
  EXPECT_NE(errorMessageOf([&] { makeScenario(options); }).find("--scenario"), std::string::npos);
}

TEST(SimOptions, NonPositiveDurationNamesTheOption) {
  for (const double duration : {-1.0, 0.0, std::nan("")}) {
    SimOptions options;
    options.duration = duration;
    EXPECT_NE(errorMessageOf([&] { validate(options); }).find("--duration"), std::string::npos) << duration;
  }
}

TEST(SimOptions, MalformedExtrinsicErrorNamesTheOption) {
  for (const char* text : {"", "1.5", "a,b", "1,2,3", "1;0.1", "-1,0.1", "1,-0.1", "nan,0.1", "200,0"})
    EXPECT_NE(errorMessageOf([&] { parseExtrinsicError(text); }).find("--extrinsic-error"), std::string::npos)
        << text;
  const ExtrinsicError e = parseExtrinsicError("2.5,0.1");
  EXPECT_DOUBLE_EQ(e.rotation_deg, 2.5);
  EXPECT_DOUBLE_EQ(e.translation_m, 0.1);
}

TEST(SimOptions, MalformedBlackoutNamesTheOption) {
  for (const char* text : {"", "3", "5,2", "-1,2", "x,2"})
    EXPECT_NE(errorMessageOf([&] { parseTimeInterval(text, "--camera-blackout"); }).find("--camera-blackout"),
              std::string::npos)
        << text;
  const TimeInterval interval = parseTimeInterval("1.5,2", "--camera-blackout");
  EXPECT_DOUBLE_EQ(interval.begin, 1.5);
  EXPECT_DOUBLE_EQ(interval.end, 2.0);
}

TEST(SimOptions, BadRealismOptionsNameTheOption) {
  const auto messageFor = [](auto change) {
    SimOptions options;
    change(options);
    return errorMessageOf([&] { validate(options); });
  };
  EXPECT_NE(messageFor([](SimOptions& o) { o.lidar = "hdl64"; }).find("--lidar"), std::string::npos);
  EXPECT_NE(messageFor([](SimOptions& o) { o.people = -1; }).find("--people"), std::string::npos);
  EXPECT_NE(messageFor([](SimOptions& o) { o.people = kMaxPeople + 1; }).find("--people"), std::string::npos);
  EXPECT_NE(messageFor([](SimOptions& o) { o.speed_scale = 0.0; }).find("--speed-scale"), std::string::npos);
  EXPECT_NE(messageFor([](SimOptions& o) { o.exposure_scale = std::nan(""); }).find("--exposure-scale"),
            std::string::npos);
  // A crowd needs walking lanes, which only the hall has.
  SimOptions room;
  room.people = 3;
  EXPECT_NE(errorMessageOf([&] { makeScenario(room); }).find("--people"), std::string::npos);
}

}  // namespace
}  // namespace lvslam::sim
