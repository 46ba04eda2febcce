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

}  // namespace
}  // namespace lvslam::sim
