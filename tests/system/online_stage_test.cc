#include "lvslam/system/online/online_stage.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/record_files.h"

namespace lvslam::system {
namespace {

// Writes down every call the stage makes, in order: what the estimator
// would compute depends on exactly this sequence.
class RecordingOutput : public OnlineOutput {
 public:
  explicit RecordingOutput(std::vector<std::string>& calls) : calls_(calls) {}
  FrameOutput add(const VisualFrameRecord* visual, const LidarFrameRecord* lidar) override {
    calls_.push_back("add " + std::to_string(added_++) + (visual ? " v" : "") +
                     (lidar ? " l" + std::to_string(lidar->lidar_features) : ""));
    return {};
  }
  void lidarImproved(std::size_t index, const LidarFrameRecord& lidar) override {
    calls_.push_back("improve " + std::to_string(index) + " l" + std::to_string(lidar.lidar_features));
  }

 private:
  std::vector<std::string>& calls_;
  int added_ = 0;
};

// `lidar_features` tags each LiDAR record: 1 the frame's first pose, 2 the improved one.
LidarFrameRecord lidarTagged(std::size_t tag) {
  LidarFrameRecord record;
  record.lidar_features = tag;
  return record;
}

struct Event {
  bool visual = false;
  std::size_t index = 0, tag = 0;
};

std::vector<std::string> callsFor(const std::vector<Event>& events) {
  std::vector<std::string> calls;
  OnlineStage stage(std::make_unique<RecordingOutput>(calls), true, true);
  for (const Event& e : events) {
    if (e.visual) stage.visualReady(e.index, VisualFrameRecord{});
    else stage.lidarReady(e.index, lidarTagged(e.tag));
  }
  return calls;
}

TEST(OnlineStage, ALateVisualRecordHoldsTheLidarsLaterRecordsSoTheOutputSeesTheOneThreadOrder) {
  // One thread: each frame is tracked before its sweep is registered. The
  // LiDAR thread posts frame 0 and 1, then (next sweep) improves them and posts 2.
  const std::vector<Event> one_thread = {{true, 0, 0},  {true, 1, 0},  {false, 0, 1}, {false, 1, 1},
                                         {true, 2, 0},  {false, 0, 2}, {false, 1, 2}, {false, 2, 1}};
  // Threaded, vision late: every LiDAR record is in before frame 0 is tracked.
  const std::vector<Event> vision_late = {{false, 0, 1}, {false, 1, 1}, {false, 0, 2}, {false, 1, 2},
                                          {false, 2, 1}, {true, 0, 0},  {true, 1, 0},  {true, 2, 0}};
  const std::vector<std::string> expected = {"add 0 v l1", "add 1 v l1", "improve 0 l2", "improve 1 l2", "add 2 v l1"};
  EXPECT_EQ(callsFor(one_thread), expected);
  EXPECT_EQ(callsFor(vision_late), expected);
}

// Improvements reach the output in the LiDAR thread's order, between the
// frames they came between; at the end the workers' records complete what
// is left.
TEST(OnlineStage, ImprovementsKeepTheLidarsOrderAndTheEndCompletesTheRest) {
  std::vector<std::string> online;
  OnlineStage stage(std::make_unique<RecordingOutput>(online), true, true);
  for (const Event& e : std::vector<Event>{{false, 0, 1}, {false, 1, 1}, {true, 0, 0}, {false, 0, 2},
                                           {true, 1, 0}, {false, 1, 2}, {false, 2, 1}, {true, 2, 0}, {true, 3, 0}}) {
    if (e.visual) stage.visualReady(e.index, VisualFrameRecord{});
    else stage.lidarReady(e.index, lidarTagged(e.tag));
  }
  const RecordFile<VisualFrameRecord> visual = testing::recordFileOf(std::vector<VisualFrameRecord>(4));
  stage.finish(visual, testing::recordFileOf(std::vector{lidarTagged(2), lidarTagged(2), lidarTagged(1), lidarTagged(9)}));
  EXPECT_EQ(online, (std::vector<std::string>{"add 0 v l1", "add 1 v l1", "improve 0 l2", "improve 1 l2",
                                              "add 2 v l1", "add 3 v l9"}));
}

TEST(OnlineStage, AFrameTheLidarNeverPosedTakesTheWorkersFinalRecordAtTheEnd) {
  std::vector<std::string> calls;
  OnlineStage stage(std::make_unique<RecordingOutput>(calls), true, true);
  stage.visualReady(0, VisualFrameRecord{});
  stage.visualReady(1, VisualFrameRecord{});
  stage.lidarReady(0, lidarTagged(1));
  stage.finish(testing::recordFileOf(std::vector<VisualFrameRecord>(2)),
               testing::recordFileOf(std::vector{lidarTagged(1), lidarTagged(7)}));
  EXPECT_EQ(calls, (std::vector<std::string>{"add 0 v l1", "add 1 v l7"}));
}

TEST(OnlineStage, WithoutALidarFramesGoOutInOrderAsTheyAreTracked) {
  std::vector<std::string> calls;
  OnlineStage stage(std::make_unique<RecordingOutput>(calls), true, false);
  stage.visualReady(1, VisualFrameRecord{});
  EXPECT_TRUE(calls.empty());
  stage.visualReady(0, VisualFrameRecord{});
  EXPECT_EQ(calls, (std::vector<std::string>{"add 0 v", "add 1 v"}));
}

}  // namespace
}  // namespace lvslam::system
