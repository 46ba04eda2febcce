// The live source: time order across two sensors that arrive in their own
// order, drops of out-of-order and late items, overflow dropping the oldest.
#include <future>
#include <thread>

#include <gtest/gtest.h>

#include "lvslam/io/live_source.h"

namespace lvslam {
namespace {

SensorData image(double t) {
  ImageFrame f;
  f.timestamp = t;
  return f;
}
SensorData scan(double t) {
  LidarScan s;
  s.timestamp = t;
  return s;
}
bool isImage(const SensorData& d) { return std::holds_alternative<ImageFrame>(d); }

LiveSourceOptions options(std::size_t capacity = 64) {
  LiveSourceOptions o;
  o.capacity = capacity;
  o.max_wait_s = 0.5;
  return o;
}

TEST(LiveSource, HandsOnInStampOrderAcrossSensors) {
  LiveSensorSource source(options());
  // A sweep stamped at its start arrives after the images taken during it.
  source.push(image(0.03));
  source.push(image(0.10));
  source.push(scan(0.0));
  source.push(scan(0.10));
  source.push(image(0.17));
  source.close();
  std::vector<std::pair<double, bool>> order;
  while (auto d = source.next()) order.emplace_back(stampOf(*d), isImage(*d));
  const std::vector<std::pair<double, bool>> expected{{0.0, false}, {0.03, true}, {0.10, false}, {0.10, true}, {0.17, true}};
  EXPECT_EQ(order, expected);
}

TEST(LiveSource, HoldsAnImageUntilTheLidarHasPassedIt) {
  LiveSensorSource source(options());
  source.push(scan(0.0));
  source.push(image(0.05));
  EXPECT_EQ(stampOf(*source.next()), 0.0);
  auto pending = std::async(std::launch::async, [&] { return source.next(); });
  EXPECT_EQ(pending.wait_for(std::chrono::milliseconds(50)), std::future_status::timeout);  // a scan at 0.04 may come
  source.push(scan(0.1));
  ASSERT_EQ(pending.wait_for(std::chrono::seconds(5)), std::future_status::ready);
  EXPECT_EQ(stampOf(*pending.get()), 0.05);
  source.close();
}

TEST(LiveSource, ASilentSensorDoesNotStallTheOther) {
  LiveSensorSource source(options());
  source.push(image(1.0));
  source.push(image(1.2));
  source.push(image(1.6));  // 0.6 s of message time without a scan
  EXPECT_EQ(stampOf(*source.next()), 1.0);
  source.close();
}

TEST(LiveSource, DropsOutOfOrderAndLateItemsAndCountsThem) {
  LiveSensorSource source(options());
  source.push(scan(0.0));
  source.push(image(0.05));
  source.push(scan(0.1));
  EXPECT_EQ(source.push(image(0.05)).verdict, LiveVerdict::kOutOfOrder);
  EXPECT_EQ(source.push(image(0.02)).verdict, LiveVerdict::kOutOfOrder);
  EXPECT_EQ(stampOf(*source.next()), 0.0);
  EXPECT_EQ(stampOf(*source.next()), 0.05);
  // A scan that comes after the image it precedes was handed on.
  LiveSensorSource other(options());
  other.push(image(0.5));
  other.push(image(1.1));
  EXPECT_EQ(stampOf(*other.next()), 0.5);  // the LiDAR stayed silent past max_wait
  EXPECT_EQ(other.push(scan(0.4)).verdict, LiveVerdict::kLate);
  const LiveSourceCounts c = other.counts();
  EXPECT_EQ(c.late, 1u);
  EXPECT_EQ(source.counts().out_of_order, 2u);
  source.close();
  other.close();
}

TEST(LiveSource, OverflowDropsTheOldest) {
  LiveSensorSource source(options(3));
  source.push(scan(0.0));
  source.push(scan(0.1));
  source.push(scan(0.2));
  EXPECT_EQ(source.push(scan(0.3)).dropped_oldest, 1u);
  source.close();
  EXPECT_EQ(stampOf(*source.next()), 0.1);
  EXPECT_EQ(source.counts().overflow, 1u);
}

TEST(LiveSource, CloseWakesAWaitingReader) {
  LiveSensorSource source(options());
  auto pending = std::async(std::launch::async, [&] { return source.next(); });
  EXPECT_EQ(pending.wait_for(std::chrono::milliseconds(20)), std::future_status::timeout);
  source.close();
  ASSERT_EQ(pending.wait_for(std::chrono::seconds(5)), std::future_status::ready);
  EXPECT_FALSE(pending.get().has_value());
  EXPECT_EQ(source.push(scan(1.0)).verdict, LiveVerdict::kQueued);  // ignored once closed
  EXPECT_FALSE(source.next().has_value());
}

TEST(LiveSource, OneSensorOnlyNeedsNoPartner) {
  LiveSourceOptions o = options();
  o.camera = false;
  LiveSensorSource source(o);
  source.push(scan(0.0));
  EXPECT_EQ(stampOf(*source.next()), 0.0);
  source.close();
}

}  // namespace
}  // namespace lvslam
