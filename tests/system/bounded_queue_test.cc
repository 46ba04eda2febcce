#include "lvslam/system/bounded_queue.h"

#include <atomic>
#include <chrono>
#include <future>
#include <thread>

#include <gtest/gtest.h>

namespace lvslam::system {
namespace {

// Generous: only guards against a hang (a wake-up that never comes), never
// measures speed.
constexpr std::chrono::seconds kHangGuard{20};

TEST(BoundedQueue, PopsInFifoOrder) {
  BoundedQueue<int> queue(4);
  for (int i = 0; i < 4; ++i) ASSERT_TRUE(queue.push(i));
  for (int i = 0; i < 4; ++i) {
    const std::optional<int> item = queue.pop();
    ASSERT_TRUE(item.has_value());
    EXPECT_EQ(*item, i);
  }
  // Refilled after draining: still in order.
  ASSERT_TRUE(queue.push(7));
  ASSERT_TRUE(queue.push(8));
  EXPECT_EQ(queue.pop(), 7);
  EXPECT_EQ(queue.pop(), 8);
}

TEST(BoundedQueue, PushBlocksWhileFullUntilAnotherThreadPops) {
  BoundedQueue<int> queue(2);
  ASSERT_TRUE(queue.push(1));
  ASSERT_TRUE(queue.push(2));
  std::atomic<bool> pushed{false};
  auto producer = std::async(std::launch::async, [&] {
    const bool ok = queue.push(3);
    pushed = true;
    return ok;
  });
  // A push that did not block would be done long before this; one that
  // blocks must still be waiting (this check can only pass wrongly, never fail wrongly).
  EXPECT_EQ(producer.wait_for(std::chrono::milliseconds(100)), std::future_status::timeout);
  EXPECT_FALSE(pushed.load());
  EXPECT_EQ(queue.pop(), 1);  // makes room
  ASSERT_EQ(producer.wait_for(kHangGuard), std::future_status::ready);
  EXPECT_TRUE(producer.get());
  EXPECT_EQ(queue.pop(), 2);
  EXPECT_EQ(queue.pop(), 3);
}

TEST(BoundedQueue, CloseWakesABlockedPop) {
  BoundedQueue<int> queue(2);
  auto consumer = std::async(std::launch::async, [&] { return queue.pop(); });
  EXPECT_EQ(consumer.wait_for(std::chrono::milliseconds(50)), std::future_status::timeout);  // empty: waits
  queue.close();
  ASSERT_EQ(consumer.wait_for(kHangGuard), std::future_status::ready);
  EXPECT_FALSE(consumer.get().has_value());
}

TEST(BoundedQueue, CloseWakesABlockedPushWhichReturnsFalse) {
  BoundedQueue<int> queue(1);
  ASSERT_TRUE(queue.push(1));
  auto producer = std::async(std::launch::async, [&] { return queue.push(2); });
  EXPECT_EQ(producer.wait_for(std::chrono::milliseconds(50)), std::future_status::timeout);  // full: waits
  queue.close();
  ASSERT_EQ(producer.wait_for(kHangGuard), std::future_status::ready);
  EXPECT_FALSE(producer.get());
  // The refused item never entered: only the one pushed before close pops.
  EXPECT_EQ(queue.pop(), 1);
  EXPECT_FALSE(queue.pop().has_value());
}

TEST(BoundedQueue, ItemsPushedBeforeCloseStillPopThenNothing) {
  BoundedQueue<int> queue(3);
  ASSERT_TRUE(queue.push(10));
  ASSERT_TRUE(queue.push(11));
  queue.close();
  EXPECT_FALSE(queue.push(12));
  EXPECT_EQ(queue.pop(), 10);
  EXPECT_EQ(queue.pop(), 11);
  EXPECT_FALSE(queue.pop().has_value());
  EXPECT_FALSE(queue.pop().has_value());  // stays drained, never blocks
}

TEST(BoundedQueue, ZeroCapacityActsAsOne) {
  BoundedQueue<int> queue(0);
  ASSERT_TRUE(queue.push(5));  // would block forever with a capacity of 0
  EXPECT_EQ(queue.pop(), 5);
}

TEST(BoundedQueue, ProducerAndConsumerThreadsPassEveryItemInOrder) {
  BoundedQueue<int> queue(3);
  constexpr int kItems = 2000;
  auto consumer = std::async(std::launch::async, [&] {
    int expected = 0;
    while (const auto item = queue.pop()) {
      if (*item != expected) return false;
      ++expected;
    }
    return expected == kItems;
  });
  for (int i = 0; i < kItems; ++i) ASSERT_TRUE(queue.push(i));
  queue.close();
  ASSERT_EQ(consumer.wait_for(kHangGuard), std::future_status::ready);
  EXPECT_TRUE(consumer.get());
}

}  // namespace
}  // namespace lvslam::system
