#include "lvslam/io/clock_check.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::errorMessageOf;

// Frames every `period` seconds over [t0, t1), numbered from line 1, with
// `shift` added from line `shift_from` on.
std::vector<TimedFile> stream(double t0, double t1, double period, int shift_from = 1 << 30, double shift = 0.0) {
  std::vector<TimedFile> files;
  for (int line = 1; t0 + (line - 1) * period < t1 - 1e-9; ++line) {
    const double t = t0 + (line - 1) * period;
    files.push_back({line >= shift_from ? t + shift : t, "", line});
  }
  return files;
}

std::vector<TimedFile> withGap(std::vector<TimedFile> files, double from, double to) {
  std::erase_if(files, [&](const TimedFile& f) { return f.t > from && f.t < to; });
  return files;
}

TEST(ClockCheck, OneStreamJumpingBeyondTheOthersEndIsNamedWithLineAndSize) {
  const auto camera = stream(0.0, 30.0, 1.0 / 15.0, 151, 100.0);
  const auto lidar = stream(0.0, 30.0, 0.1);
  const std::string msg = errorMessageOf([&] { checkClocksAgree(camera, "camera/times.txt", lidar, "lidar/times.txt"); });
  EXPECT_EQ(msg.rfind("camera/times.txt:151: ", 0), 0u) << msg;
  EXPECT_NE(msg.find("jumps by 100.067 s"), std::string::npos) << msg;
  EXPECT_NE(msg.find("lidar/times.txt"), std::string::npos) << msg;
  // The same either way round.
  const std::string swapped = errorMessageOf([&] { checkClocksAgree(lidar, "lidar/times.txt", camera, "camera/times.txt"); });
  EXPECT_EQ(swapped.rfind("camera/times.txt:151: ", 0), 0u) << swapped;
}

TEST(ClockCheck, AStreamThatLayBeforeTheOthersStartIsAJumpToo) {
  // The first lines 100 s early, the rest on time: the jump is where they meet.
  auto lidar = stream(0.0, 30.0, 0.1);
  for (std::size_t i = 0; i < 20; ++i) lidar[i].t -= 100.0;
  const auto camera = stream(2.0, 30.0, 1.0 / 15.0);
  const std::string msg = errorMessageOf([&] { checkClocksAgree(camera, "c", lidar, "l"); });
  EXPECT_EQ(msg.rfind("l:21: ", 0), 0u) << msg;
  EXPECT_NE(msg.find("first stamp of c"), std::string::npos) << msg;
}

TEST(ClockCheck, ADropOutOfOneSensorIsNotAJump) {
  const auto camera = stream(0.0, 30.0, 1.0 / 15.0);
  const auto lidar = withGap(stream(0.0, 30.0, 0.1), 10.0, 12.0);
  EXPECT_EQ(errorMessageOf([&] { checkClocksAgree(camera, "c", lidar, "l"); }), "");
  // A drop-out at the end: the stream stops, nothing resumes.
  EXPECT_EQ(errorMessageOf([&] { checkClocksAgree(camera, "c", stream(0.0, 20.0, 0.1), "l"); }), "");
}

TEST(ClockCheck, BothSensorsPausingTogetherIsNotAJump) {
  const auto camera = withGap(stream(0.0, 30.0, 1.0 / 15.0), 10.0, 15.0);
  const auto lidar = withGap(stream(0.0, 30.0, 0.1), 10.0, 15.0);
  EXPECT_EQ(errorMessageOf([&] { checkClocksAgree(camera, "c", lidar, "l"); }), "");
}

TEST(ClockCheck, TooFewFramesToJudge) {
  EXPECT_EQ(errorMessageOf([&] { checkClocksAgree(stream(0.0, 0.2, 0.1), "c", stream(100.0, 130.0, 0.1), "l"); }), "");
  EXPECT_EQ(errorMessageOf([&] { checkClocksAgree({}, "c", stream(0.0, 30.0, 0.1), "l"); }), "");
}

}  // namespace
}  // namespace lvslam
