// The real bag of ../shared/data/ros1 (embag's test bag), read as a list of
// topics, as scans checked against an independent decoding of the raw
// messages, and cut off part way.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>
#include <spdlog/sinks/ostream_sink.h>
#include <spdlog/spdlog.h>

#include "lvslam/io/pointcloud2_decoder.h"
#include "lvslam/io/rosbag_reader.h"
#include "lvslam/io/rosbag_source.h"
#include "lvslam/io/rosbag_msgs.h"
#include "lvslam/io/rosbag_convert.h"
#include "lvslam/io/sequence_reader.h"
#include "support/temp_dir.h"

#include <rosbag/bag.h>
#include <rosbag/view.h>

namespace lvslam {
namespace {

const std::string kBag = std::string(LVSLAM_SHARED_DATA_DIR) + "/ros1/embag-test.bag";
const std::string kCloudTopic = "/luminar_pointcloud";

// The bag lives outside the repository; like the other shared-data tests these
// skip, naming the path, when a checkout is not beside ../shared.
class RealBag : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(kBag)) GTEST_SKIP() << "shared test data not found: " << kBag;
  }
};

// The expected scan of a raw message, computed here from the bytes and the
// fields' documented layout (x y z float32 at 0 4 8, intensity float32 at 16,
// time_sec time_nsec uint32 at 20 24, laser_id uint16 at 28).
LidarScan expectedScan(const rosmsg::PointCloud2& cloud) {
  LidarScan scan;
  scan.timestamp = cloud.header.stamp.toSec();
  for (std::size_t i = 0; i < std::size_t{cloud.width} * cloud.height; ++i) {
    const std::uint8_t* p = cloud.data.data() + i * cloud.point_step;
    float xyz[3], intensity;
    std::uint32_t sec, nsec;
    std::uint16_t laser;
    std::memcpy(xyz, p, 12);
    std::memcpy(&intensity, p + 16, 4);
    std::memcpy(&sec, p + 20, 4);
    std::memcpy(&nsec, p + 24, 4);
    std::memcpy(&laser, p + 28, 2);
    if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]) ||
        (xyz[0] == 0 && xyz[1] == 0 && xyz[2] == 0))
      continue;
    LidarPoint lp;
    lp.p = {xyz[0], xyz[1], xyz[2]};
    lp.intensity = intensity;
    lp.ring = laser;
    const std::int64_t ns = (std::int64_t{sec} - cloud.header.stamp.sec) * 1000000000 +
                            (std::int64_t{nsec} - cloud.header.stamp.nsec);
    lp.time = static_cast<float>(ns * 1e-9);
    scan.points.push_back(lp);
  }
  return scan;
}

std::vector<rosmsg::PointCloud2> rawClouds(const std::string& path) {
  rosbag::Bag bag(path);
  std::vector<rosmsg::PointCloud2> out;
  for (const rosbag::MessageInstance& m : rosbag::View(bag, rosbag::TopicQuery(kCloudTopic)))
    out.push_back(*m.instantiate<rosmsg::PointCloud2>());
  return out;
}

void expectSameScan(const LidarScan& expected, const LidarScan& actual) {
  ASSERT_EQ(expected.size(), actual.size());
  EXPECT_DOUBLE_EQ(expected.timestamp, actual.timestamp);
  for (std::size_t i = 0; i < expected.size(); ++i) {
    ASSERT_EQ(expected.points[i].p, actual.points[i].p) << i;
    ASSERT_EQ(expected.points[i].intensity, actual.points[i].intensity) << i;
    ASSERT_EQ(expected.points[i].ring, actual.points[i].ring) << i;
    ASSERT_NEAR(expected.points[i].time, actual.points[i].time, 1e-7) << i;
  }
}

TEST_F(RealBag, ListsTheTopicsOfTheRealBag) {
  const RosbagReader bag(kBag);
  const std::vector<BagTopicInfo> topics = bag.topics();
  ASSERT_EQ(topics.size(), 3u);
  EXPECT_EQ(topics[0].topic, "/base_pose_ground_truth");
  EXPECT_EQ(topics[0].type, "nav_msgs/Odometry");
  EXPECT_EQ(topics[0].messages, 5u);
  EXPECT_EQ(topics[1].topic, "/base_scan");
  EXPECT_EQ(topics[1].type, "sensor_msgs/LaserScan");
  EXPECT_EQ(topics[1].messages, 5u);
  EXPECT_EQ(topics[2].topic, "/luminar_pointcloud");
  EXPECT_EQ(topics[2].type, "sensor_msgs/PointCloud2");
  EXPECT_EQ(topics[2].messages, 5u);
  EXPECT_NEAR(bag.beginTime(), 1604515190.231, 1e-3);
  EXPECT_NEAR(bag.endTime(), 1604515197.820, 1e-3);
  EXPECT_TRUE(bag.damage().empty());
}

TEST_F(RealBag, DecodesTheRealPointCloudsByFieldName) {
  const std::vector<rosmsg::PointCloud2> raw = rawClouds(kBag);
  ASSERT_EQ(raw.size(), 5u);
  BagSourceOptions options;
  options.lidar_topic = kCloudTopic;
  BagSource source({kBag}, options);
  std::size_t n = 0;
  while (auto data = source.next()) {
    ASSERT_LT(n, raw.size());
    const LidarScan expected = expectedScan(raw[n]);
    const auto& scan = std::get<LidarScan>(*data);
    EXPECT_TRUE(scan.has_time && scan.has_intensity && scan.has_ring);
    expectSameScan(expected, scan);
    // The stamp is the end of the Luminar sweep: every point time <= 0, the last at 0.
    float latest = -1.0f;
    for (const LidarPoint& p : scan.points) latest = std::max(latest, p.time);
    EXPECT_EQ(latest, 0.0f);
    ++n;
  }
  EXPECT_EQ(n, 5u);
  const LidarInfo info = source.lidarInfo();
  EXPECT_EQ(info.time_reference, TimeReference::kEnd);
  EXPECT_EQ(info.point_fields, (std::vector<std::string>{"x", "y", "z", "intensity", "time", "ring"}));
}

TEST_F(RealBag, ConvertsTheRealBagToASequenceFolder) {
  testing::TempDir dir;
  BagConvertOptions options;
  options.bags = {kBag};
  options.lidar_topic = kCloudTopic;
  options.out_dir = dir.file("seq");
  const BagConvertStats stats = convertBags(options);
  EXPECT_EQ(stats.scans, 5u);
  SequenceReader reader(dir.file("seq"));
  ASSERT_TRUE(reader.info().lidar.has_value());
  EXPECT_EQ(reader.info().lidar->time_reference, TimeReference::kEnd);
  const std::vector<rosmsg::PointCloud2> raw = rawClouds(kBag);
  ASSERT_EQ(reader.lidarFiles().size(), raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    const LidarScan expected = expectedScan(raw[i]);
    const LidarScan scan = reader.loadScan(i);
    // sequence files hold the time stamp with nanosecond digits and float32 fields
    EXPECT_NEAR(scan.timestamp, expected.timestamp, 1e-6);
    ASSERT_EQ(scan.size(), expected.size());
    EXPECT_EQ(scan.points[100].p, expected.points[100].p);
    EXPECT_EQ(scan.points.back().time, expected.points.back().time);
  }
}

struct WarningCapture {
  WarningCapture() : sink(std::make_shared<spdlog::sinks::ostream_sink_mt>(text)) {
    spdlog::default_logger()->sinks().push_back(sink);
  }
  ~WarningCapture() {
    auto& sinks = spdlog::default_logger()->sinks();
    sinks.erase(std::remove(sinks.begin(), sinks.end(), sink), sinks.end());
  }
  std::ostringstream text;
  std::shared_ptr<spdlog::sinks::ostream_sink_mt> sink;
};

void copyPrefix(const std::string& from, const std::string& to, std::size_t bytes) {
  std::ifstream in(from, std::ios::binary);
  std::vector<char> data(bytes);
  in.read(data.data(), static_cast<std::streamsize>(bytes));
  std::ofstream(to, std::ios::binary).write(data.data(), in.gcount());
}

TEST_F(RealBag, ReadsATruncatedBagUpToTheDamageWithAWarning) {
  testing::TempDir dir;
  const std::vector<rosmsg::PointCloud2> raw = rawClouds(kBag);
  const std::size_t full_size = std::filesystem::file_size(kBag);
  std::size_t previous = 0;
  for (const double fraction : {0.35, 0.6, 0.9}) {
    const std::string cut = dir.file("cut.bag");
    copyPrefix(kBag, cut, static_cast<std::size_t>(fraction * full_size));
    WarningCapture warnings;
    BagSourceOptions options;
    options.lidar_topic = kCloudTopic;
    BagSource source({cut}, options);
    std::size_t n = 0;
    while (auto data = source.next()) expectSameScan(expectedScan(raw[n++]), std::get<LidarScan>(*data));
    // Fewer clouds than the whole bag, more the more of the file there is.
    EXPECT_LT(n, raw.size()) << fraction;
    EXPECT_GE(n, previous) << fraction;
    previous = n;
    EXPECT_NE(warnings.text.str().find("damaged bag"), std::string::npos);
    EXPECT_NE(warnings.text.str().find(cut), std::string::npos);
    const RosbagReader reader(cut);
    EXPECT_NE(reader.damage().find("cut off"), std::string::npos) << reader.damage();
  }
  EXPECT_GT(previous, 0u);
}

TEST_F(RealBag, ABagCutBeforeItsFirstMessageIsAnError) {
  testing::TempDir dir;
  const std::string cut = dir.file("cut.bag");
  copyPrefix(kBag, cut, 5000);
  const std::string message = testing::errorMessageOf([&] { RosbagReader reader(cut); });
  EXPECT_NE(message.find(cut), std::string::npos) << message;
  EXPECT_NE(message.find("no readable message"), std::string::npos) << message;
  testing::TempDir other;
  other.write("not.bag", "hello, this is not a bag\n");
  const std::string not_bag = testing::errorMessageOf([&] { RosbagReader reader(other.file("not.bag")); });
  EXPECT_NE(not_bag.find("not a ROS1 bag"), std::string::npos) << not_bag;
}

}  // namespace
}  // namespace lvslam
