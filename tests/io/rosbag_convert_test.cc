// Bags written with rosbag_storage's own writer, converted to sequence
// folders and compared with what was written; bad input named precisely.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <regex>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "lvslam/io/pointcloud2_decoder.h"
#include "lvslam/io/rosbag_reader.h"
#include "lvslam/io/rosbag_convert.h"
#include "lvslam/io/rosbag_source.h"
#include "lvslam/io/sequence_reader.h"
#include "rosbag_test_messages.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::VelodynePoint;

constexpr int kWidth = 40, kHeight = 30;
constexpr double kT0 = 1628249320.0;

cv::Mat randomImage(int type, unsigned seed) {
  cv::Mat image(kHeight, kWidth, type);
  cv::RNG rng(seed);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  return image;
}

// A smooth image: JPEG keeps it close, so the comparison is meaningful.
cv::Mat smoothImage(unsigned seed) {
  cv::Mat image(kHeight, kWidth, CV_8UC3);
  for (int r = 0; r < kHeight; ++r)
    for (int c = 0; c < kWidth; ++c)
      image.at<cv::Vec3b>(r, c) = cv::Vec3b(static_cast<uchar>(4 * r + seed), static_cast<uchar>(5 * c), 128);
  return image;
}

std::vector<VelodynePoint> sweep(unsigned seed, bool end_stamped) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> coord(-20.0f, 20.0f), t(0.0f, 0.1f);
  std::vector<VelodynePoint> points;
  for (int i = 0; i < 200; ++i)
    points.push_back({coord(rng), coord(rng), coord(rng), float(i % 100), static_cast<std::uint16_t>(i % 32),
                      end_stamped ? -t(rng) : t(rng)});
  points[7].x = std::numeric_limits<float>::quiet_NaN();  // invalid returns, dropped
  points[11] = {0.0f, 0.0f, 0.0f, 3.0f, 1, 0.01f};
  return points;
}

std::vector<std::uint8_t> encode(const std::string& ext, const cv::Mat& image) {
  std::vector<std::uint8_t> bytes;
  cv::imencode(ext, image, bytes);
  return bytes;
}

struct WrittenBag {
  std::vector<cv::Mat> mono, bgr, rgb_as_bgr, png, jpeg_decoded, jpeg_source;
  std::vector<std::vector<VelodynePoint>> clouds;
  std::vector<double> image_times, cloud_times;
};

// Images at 15 Hz on five topics, clouds at 10 Hz, written in two files.
WrittenBag writeBags(const std::string& first, const std::string& second, bool end_stamped = false) {
  WrittenBag w;
  rosbag::Bag a(first, rosbag::bagmode::Write), b(second, rosbag::bagmode::Write);
  a.setCompression(rosbag::compression::LZ4);
  for (int i = 0; i < 6; ++i) {
    rosbag::Bag& bag = i < 3 ? a : b;
    const double t = kT0 + i / 15.0;
    w.image_times.push_back(t);
    w.mono.push_back(randomImage(CV_8UC1, 10 + i));
    w.bgr.push_back(randomImage(CV_8UC3, 20 + i));
    const cv::Mat rgb = randomImage(CV_8UC3, 30 + i);
    cv::Mat as_bgr;
    cv::cvtColor(rgb, as_bgr, cv::COLOR_RGB2BGR);
    w.rgb_as_bgr.push_back(as_bgr);
    w.png.push_back(randomImage(CV_8UC3, 40 + i));
    w.jpeg_source.push_back(smoothImage(i));
    const std::vector<std::uint8_t> jpeg = encode(".jpg", w.jpeg_source.back());
    w.jpeg_decoded.push_back(cv::imdecode(jpeg, cv::IMREAD_UNCHANGED));
    const ros::Time rec = testing::rosTime(t + 0.003);  // record time: a little after the stamp
    bag.write("/mono", rec, testing::rawImage(t, w.mono.back(), "mono8"));
    bag.write("/bgr", rec, testing::rawImage(t, w.bgr.back(), "bgr8"));
    bag.write("/rgb", rec, testing::rawImage(t, rgb, "rgb8"));
    bag.write("/png", rec, testing::compressedImage(t, encode(".png", w.png.back()), "png"));
    bag.write("/jpeg", rec, testing::compressedImage(t, jpeg, "bgr8; jpeg compressed bgr8"));
  }
  for (int i = 0; i < 4; ++i) {
    const double t = kT0 + 0.01 + i * 0.1;
    w.cloud_times.push_back(t);
    w.clouds.push_back(sweep(50 + i, end_stamped));
    (t < kT0 + 0.2 ? a : b).write("/velodyne_points", testing::rosTime(t + 0.05), testing::velodyneCloud(t, w.clouds.back()));
  }
  return w;
}

std::string writePreset(const testing::TempDir& dir) {
  dir.write("preset.yaml", R"(format: lvslam-preset/1
name: test-rig
topics:
  lidar: /velodyne_points
camera:
  model: pinhole
  width: 40
  height: 30
  intrinsics: [50, 51, 20, 15]
lidar:
  rings: 32
extrinsics:
  T_camera_lidar: [0, -1, 0, 0.1,  0, 0, -1, 0.2,  1, 0, 0, 0.3,  0, 0, 0, 1]
groundtruth:
  frame: lidar
)");
  return dir.file("preset.yaml");
}

double maxAbsDiff(const cv::Mat& a, const cv::Mat& b) {
  double m = 0.0;
  cv::minMaxLoc(cv::abs(a - b), nullptr, &m);
  return m;
}

TEST(RosbagConvert, ImagesOfEveryEncodingRoundTrip) {
  testing::TempDir dir;
  // The later file given first: files are read in time order.
  const WrittenBag w = writeBags(dir.file("a.bag"), dir.file("b.bag"));
  const SensorPreset preset = loadSensorPreset(writePreset(dir));
  const std::vector<std::pair<std::string, const std::vector<cv::Mat>*>> topics{
      {"/mono", &w.mono}, {"/bgr", &w.bgr}, {"/rgb", &w.rgb_as_bgr}, {"/png", &w.png}, {"/jpeg", &w.jpeg_decoded}};
  for (const auto& [topic, expected] : topics) {
    BagConvertOptions options;
    options.bags = {dir.file("b.bag"), dir.file("a.bag")};
    options.camera_topic = topic;
    options.preset = preset;
    options.out_dir = dir.file("seq" + topic);
    const BagConvertStats stats = convertBags(options);
    EXPECT_EQ(stats.images, 6u) << topic;
    EXPECT_EQ(stats.scans, 4u) << topic;
    SequenceReader reader(options.out_dir);
    ASSERT_EQ(reader.cameraFiles().size(), 6u) << topic;
    EXPECT_EQ(reader.info().camera->camera.fx(), 50.0);
    for (std::size_t i = 0; i < 6; ++i) {
      const ImageFrame frame = reader.loadImage(i);
      EXPECT_NEAR(frame.timestamp, w.image_times[i], 1e-6) << topic;
      ASSERT_EQ(frame.image.type(), (*expected)[i].type()) << topic;
      EXPECT_EQ(maxAbsDiff(frame.image, (*expected)[i]), 0.0) << topic << " image " << i;
    }
  }
  // JPEG is lossy: the decoded frames are still close to what was encoded.
  for (std::size_t i = 0; i < 6; ++i) EXPECT_LT(cv::norm(w.jpeg_decoded[i], w.jpeg_source[i], cv::NORM_L1) / (kWidth * kHeight * 3), 3.0);
}

void expectPoints(const std::vector<VelodynePoint>& written, const LidarScan& scan) {
  std::size_t k = 0;
  for (std::size_t i = 0; i < written.size(); ++i) {
    const VelodynePoint& w = written[i];
    if (!std::isfinite(w.x) || (w.x == 0 && w.y == 0 && w.z == 0)) continue;
    ASSERT_LT(k, scan.size());
    const LidarPoint& p = scan.points[k++];
    EXPECT_EQ(p.p, Eigen::Vector3f(w.x, w.y, w.z));
    EXPECT_EQ(p.intensity, w.intensity);
    EXPECT_EQ(p.ring, w.ring);
    EXPECT_EQ(p.time, w.time);
  }
  EXPECT_EQ(k, scan.size());
  EXPECT_EQ(scan.size(), written.size() - 2);
}

TEST(RosbagConvert, VelodyneCloudsRoundTripWithTimesAndRings) {
  for (const bool end_stamped : {false, true}) {
    testing::TempDir dir;
    const WrittenBag w = writeBags(dir.file("a.bag"), dir.file("b.bag"), end_stamped);
    BagConvertOptions options;
    options.bags = {dir.file("a.bag"), dir.file("b.bag")};
    options.preset = loadSensorPreset(writePreset(dir));
    options.camera_topic = "/mono";
    options.out_dir = dir.file("seq");
    convertBags(options);
    SequenceReader reader(options.out_dir);
    EXPECT_EQ(reader.info().lidar->time_reference, end_stamped ? TimeReference::kEnd : TimeReference::kStart);
    EXPECT_EQ(reader.info().lidar->rings, 32);
    EXPECT_NEAR(reader.info().T_camera_lidar.translation().z(), 0.3, 1e-15);
    ASSERT_EQ(reader.lidarFiles().size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
      const LidarScan scan = reader.loadScan(i);
      EXPECT_NEAR(scan.timestamp, w.cloud_times[i], 1e-6);
      expectPoints(w.clouds[i], scan);
    }
    // Merged by stamp: scans and images in time order.
    std::vector<double> stamps;
    reader.rewind();
    while (auto d = reader.next()) stamps.push_back(std::visit([](const auto& x) { return x.timestamp; }, *d));
    EXPECT_EQ(stamps.size(), 10u);
    EXPECT_TRUE(std::is_sorted(stamps.begin(), stamps.end()));
  }
}

// A cloud in another layout: big-endian, float64 coordinates, an Ouster-like
// uint32 `t` in nanoseconds, padded rows (row_step > width * point_step).
TEST(RosbagConvert, DecodesOtherDatatypesByteOrderAndRowStep) {
  rosmsg::PointCloud2 cloud;
  cloud.header.stamp = testing::rosTime(kT0);
  cloud.height = 2;
  cloud.width = 3;
  cloud.is_bigendian = 1;
  cloud.fields = {testing::pointField("t", 0, 6), testing::pointField("z", 4, 8), testing::pointField("y", 12, 8),
                  testing::pointField("x", 20, 8), testing::pointField("intensity", 28, 2)};
  cloud.point_step = 29;
  cloud.row_step = 3 * 29 + 5;
  cloud.data.assign(2 * cloud.row_step, 0xEE);
  auto putBig = [](std::uint8_t* p, const void* v, int n) {
    for (int i = 0; i < n; ++i) p[i] = static_cast<const std::uint8_t*>(v)[n - 1 - i];
  };
  for (std::uint32_t r = 0; r < 2; ++r) {
    for (std::uint32_t c = 0; c < 3; ++c) {
      std::uint8_t* p = cloud.data.data() + r * cloud.row_step + c * cloud.point_step;
      const std::uint32_t t_ns = 1000000 * (r * 3 + c);
      const double x = 1.5 + c, y = -2.25 * r, z = 0.125;
      const std::uint8_t intensity = static_cast<std::uint8_t>(10 * c);
      putBig(p, &t_ns, 4);
      putBig(p + 4, &z, 8);
      putBig(p + 12, &y, 8);
      putBig(p + 20, &x, 8);
      p[28] = intensity;
    }
  }
  std::vector<std::uint8_t> bytes(ros::serialization::serializationLength(cloud));
  ros::serialization::OStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  ros::serialization::serialize(stream, cloud);
  const DecodedScan d = decodePointCloud2(bytes, "test");
  ASSERT_EQ(d.scan.size(), 6u);
  ASSERT_EQ(d.time_reference, TimeReference::kStart);
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t r = i / 3, c = i % 3;
    EXPECT_EQ(d.scan.points[i].p, Eigen::Vector3f(1.5f + c, -2.25f * r, 0.125f));
    EXPECT_FLOAT_EQ(d.scan.points[i].time, 1e-3f * i);
    EXPECT_EQ(d.scan.points[i].intensity, 10.0f * c);
  }
  EXPECT_FALSE(d.scan.has_ring);
}

// A stamp inside the sweep (times on both sides) is moved to the sweep start.
TEST(RosbagConvert, AStampInsideTheSweepIsMovedToItsStart) {
  std::vector<VelodynePoint> points{{1, 0, 0, 0, 0, -0.05f}, {2, 0, 0, 0, 0, 0.0f}, {3, 0, 0, 0, 0, 0.05f}};
  const rosmsg::PointCloud2 cloud = testing::velodyneCloud(kT0, points);
  std::vector<std::uint8_t> bytes(ros::serialization::serializationLength(cloud));
  ros::serialization::OStream stream(bytes.data(), static_cast<std::uint32_t>(bytes.size()));
  ros::serialization::serialize(stream, cloud);
  const DecodedScan d = decodePointCloud2(bytes, "test");
  EXPECT_TRUE(d.restamped);
  EXPECT_EQ(d.time_reference, TimeReference::kStart);
  EXPECT_NEAR(d.scan.timestamp, kT0 - 0.05, 1e-7);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_NEAR(d.scan.pointTime(i), kT0 + points[i].time, 1e-7);
}

// --- bad input: one lvslam::Error naming bag, topic and field ---

std::string writeOneMessageBag(const testing::TempDir& dir, const std::string& topic, auto message) {
  const std::string path = dir.file("bad.bag");
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  bag.write(topic, testing::rosTime(kT0), message);
  return path;
}

void expectMentions(const std::string& message, const std::vector<std::string>& words) {
  EXPECT_FALSE(message.empty());
  for (const std::string& w : words) EXPECT_NE(message.find(w), std::string::npos) << message << " lacks " << w;
}

std::string convertError(const std::string& bag, const std::string& lidar, const std::string& camera,
                         const testing::TempDir& dir) {
  BagConvertOptions options;
  options.bags = {bag};
  options.lidar_topic = lidar;
  options.camera_topic = camera;
  options.preset = loadSensorPreset(writePreset(dir));
  options.preset->lidar_topic.clear();
  options.out_dir = dir.file("out");
  return testing::errorMessageOf([&] { convertBags(options); });
}

TEST(RosbagConvertBadInput, MissingTopicNamesBagAndTopic) {
  testing::TempDir dir;
  const std::string bag = writeOneMessageBag(dir, "/mono", testing::rawImage(kT0, randomImage(CV_8UC1, 1), "mono8"));
  expectMentions(convertError(bag, "/velodyne_points", "", dir), {bag, "/velodyne_points", "not found", "/mono"});
  expectMentions(convertError(bag, "/mono", "", dir), {bag, "/mono", "sensor_msgs/Image", "not sensor_msgs/PointCloud2"});
}

TEST(RosbagConvertBadInput, UnknownEncodingNamesBagTopicAndEncoding) {
  testing::TempDir dir;
  const std::string bag = writeOneMessageBag(dir, "/cam", testing::rawImage(kT0, randomImage(CV_8UC1, 1), "bayer_rggb8"));
  expectMentions(convertError(bag, "", "/cam", dir), {bag, "/cam", "bayer_rggb8"});
  testing::TempDir dir2;
  const std::string bag2 = writeOneMessageBag(dir2, "/cam", testing::compressedImage(kT0, {1, 2, 3}, "tiff"));
  expectMentions(convertError(bag2, "", "/cam", dir2), {bag2, "/cam", "tiff"});
  testing::TempDir dir3;
  const std::string bag3 = writeOneMessageBag(dir3, "/cam", testing::compressedImage(kT0, {1, 2, 3}, "png"));
  expectMentions(convertError(bag3, "", "/cam", dir3), {bag3, "/cam", "cannot decode"});
  testing::TempDir dir4;
  std::vector<std::uint8_t> png = encode(".png", randomImage(CV_8UC3, 4));
  png.resize(png.size() / 2);
  const std::string bag4 = writeOneMessageBag(dir4, "/cam", testing::compressedImage(kT0, png, "png"));
  expectMentions(convertError(bag4, "", "/cam", dir4), {bag4, "/cam", "damaged PNG: the file ends at byte"});
  // Found by fuzz_ros_image: data that is not PNG or JPEG (here a JPEG 2000
  // signature) under a png format never reaches OpenCV's other decoders.
  testing::TempDir dir5;
  const std::vector<std::uint8_t> jp2 = {0x00, 0x00, 0x00, 0x0c, 'j', 'P', ' ', ' ', 0x0d, 0x0a, 0x87, 0x0a};
  const std::string bag5 = writeOneMessageBag(dir5, "/cam", testing::compressedImage(kT0, jp2, "png"));
  expectMentions(convertError(bag5, "", "/cam", dir5), {bag5, "/cam", "neither PNG nor JPEG"});
  // A failed conversion leaves nothing: no folder, no partial one.
  EXPECT_FALSE(std::filesystem::exists(dir3.file("out")));
  EXPECT_FALSE(std::filesystem::exists(dir3.file("out.partial")));
}

// Ten clouds, each in its own LZ4 chunk; returns the byte offset of the
// compressed data of chunk `damaged` (0-based), whose 8 bytes there are overwritten.
std::size_t writeBagWithADamagedChunk(const std::string& path, int damaged) {
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    bag.setCompression(rosbag::compression::LZ4);
    bag.setChunkThreshold(1024);
    for (int i = 0; i < 10; ++i)
      bag.write("/velodyne_points", testing::rosTime(kT0 + 0.1 * i + 0.05),
                testing::velodyneCloud(kT0 + 0.1 * i, sweep(60 + i, false)));
  }
  std::string bytes = testing::slurpBinary(path);
  std::size_t chunk = 0;
  for (int i = 0; i <= damaged; ++i) chunk = bytes.find("compression=lz4", chunk + 1);
  const std::size_t at = chunk + 200;  // well inside the chunk's compressed data
  bytes.replace(at, 8, 8, '\x5a');
  std::ofstream(path, std::ios::binary) << bytes;
  return at;
}

TEST(RosbagConvertDamaged, ADamagedChunkIsConvertedUpToWithItsOffsetTopicAndTime) {
  testing::TempDir dir;
  const std::string bag = dir.file("damaged.bag");
  const std::size_t damaged_at = writeBagWithADamagedChunk(bag, 4);
  RosbagReader reader(bag);
  std::size_t read = 0;
  while (reader.next()) ++read;
  EXPECT_EQ(read, 4u) << "the four clouds before the damaged chunk";
  expectMentions(reader.damage(), {"/velodyne_points", fmt::format("{:.6f}", kT0 + 0.45), "lz4 chunk at byte",
                                   "does not decompress"});
  std::smatch offset;
  ASSERT_TRUE(std::regex_search(reader.damage(), offset, std::regex(R"(chunk at byte (\d+))"))) << reader.damage();
  const std::size_t chunk_at = std::stoul(offset[1]);
  EXPECT_LT(chunk_at, damaged_at);
  EXPECT_GT(chunk_at + 250, damaged_at) << "the record holding the overwritten bytes";

  BagConvertOptions options;
  options.bags = {bag};
  options.lidar_topic = "/velodyne_points";
  options.out_dir = dir.file("out");
  EXPECT_EQ(convertBags(options).scans, 4u);
  EXPECT_EQ(SequenceReader(dir.file("out")).lidarFiles().size(), 4u);
}

TEST(RosbagConvertAtomic, ReplacesAnEarlierSequenceButNoOtherFolder) {
  testing::TempDir dir;
  const std::string bag = writeOneMessageBag(dir, "/velodyne_points", testing::velodyneCloud(kT0, sweep(1, false)));
  BagConvertOptions options;
  options.bags = {bag};
  options.lidar_topic = "/velodyne_points";
  options.out_dir = dir.file("out");
  dir.write("out/sequence.yaml", "an earlier conversion\n");
  dir.write("out/lidar/stale.bin", "x");
  EXPECT_EQ(convertBags(options).scans, 1u);
  EXPECT_FALSE(std::filesystem::exists(dir.file("out/lidar/stale.bin")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("out/INCOMPLETE")));
  EXPECT_FALSE(std::filesystem::exists(dir.file("out.partial")));
  SequenceReader reader(dir.file("out"));
  EXPECT_EQ(reader.lidarFiles().size(), 1u);

  options.out_dir = dir.file("mine");
  dir.write("mine/notes.txt", "the user's own\n");
  expectMentions(testing::errorMessageOf([&] { convertBags(options); }), {"mine", "not a sequence folder"});
  EXPECT_TRUE(std::filesystem::exists(dir.file("mine/notes.txt")));
}

TEST(RosbagConvertBadInput, CloudWithoutXNamesBagTopicAndField) {
  testing::TempDir dir;
  rosmsg::PointCloud2 cloud = testing::velodyneCloud(kT0, sweep(1, false));
  cloud.fields.erase(cloud.fields.begin());  // no x
  const std::string bag = writeOneMessageBag(dir, "/velodyne_points", cloud);
  expectMentions(convertError(bag, "/velodyne_points", "", dir), {bag, "/velodyne_points", "'x'"});

  testing::TempDir dir2;
  rosmsg::PointCloud2 short_cloud = testing::velodyneCloud(kT0, sweep(1, false));
  short_cloud.data.resize(short_cloud.data.size() / 2);  // the layout claims more points than the data has
  const std::string bag2 = writeOneMessageBag(dir2, "/velodyne_points", short_cloud);
  expectMentions(convertError(bag2, "/velodyne_points", "", dir2), {bag2, "/velodyne_points", "needs"});

  testing::TempDir dir3;
  rosmsg::PointCloud2 bad_field = testing::velodyneCloud(kT0, sweep(1, false));
  bad_field.fields[5].offset = 30;  // time: float32 at 30 runs past point_step 32
  const std::string bag3 = writeOneMessageBag(dir3, "/velodyne_points", bad_field);
  expectMentions(convertError(bag3, "/velodyne_points", "", dir3), {bag3, "/velodyne_points", "'time'"});

  testing::TempDir dir4;
  rosmsg::PointCloud2 overlapping = testing::velodyneCloud(kT0, sweep(1, false));
  overlapping.height = 1000000;  // rows of no length: a few bytes would claim a million sweeps (found by fuzzing)
  overlapping.row_step = 0;
  const std::string bag4 = writeOneMessageBag(dir4, "/velodyne_points", overlapping);
  expectMentions(convertError(bag4, "/velodyne_points", "", dir4),
                 {bag4, "/velodyne_points", "row_step 0 is shorter than a row of 200 points of point_step 32"});
}

// ---- The two sensors' clocks checked against each other as a bag is read:
// clouds at 10 Hz and images at 15 Hz for 2 s, recorded a few ms after
// their stamps; from image `jump_from` on the camera stamps are shifted by
// `camera_jump` s (its clock jumped; record times go on), and the images of
// [gap_from, gap_to) s are not in the bag at all (a drop-out).
std::string writeTwoClockBag(const testing::TempDir& dir, int jump_from, double camera_jump, double gap_from = 9.0,
                             double gap_to = 9.0) {
  const std::string path = dir.file("clocks.bag");
  rosbag::Bag bag(path, rosbag::bagmode::Write);
  for (int i = 0; i < 20; ++i)
    bag.write("/velodyne_points", testing::rosTime(kT0 + 0.1 * i + 0.104),
              testing::velodyneCloud(kT0 + 0.1 * i, sweep(70 + i, false)));
  for (int i = 0; i < 30; ++i) {
    const double t = kT0 + i / 15.0;
    if (t - kT0 >= gap_from && t - kT0 < gap_to) continue;
    const double stamp = i >= jump_from ? t + camera_jump : t;
    bag.write("/mono", testing::rosTime(t + 0.003), testing::rawImage(stamp, randomImage(CV_8UC1, i), "mono8"));
  }
  return path;
}

// Reads every item of a bag source; returns how many, or throws its error.
std::size_t readAll(const std::string& bag) {
  BagSourceOptions options;
  options.lidar_topic = "/velodyne_points";
  options.camera_topic = "/mono";
  BagSource source({bag}, options);
  std::size_t items = 0;
  while (source.next()) ++items;
  return items;
}

TEST(RosbagClocks, OneSensorsClockJumpIsNamedWithTopicStampAndSize) {
  testing::TempDir dir;
  const std::string bag = writeTwoClockBag(dir, 12, 100.0);
  const std::string message = testing::errorMessageOf([&] { readAll(bag); });
  EXPECT_NE(message.find(bag + " topic /mono: time stamp " + fmt::format("{:.6f}", kT0 + 12 / 15.0 + 100.0) +
                         " jumps by +100.000 s against its record time while the stamps of topic /velodyne_points do not"),
            std::string::npos)
      << message;
}

TEST(RosbagClocks, TheLidarsClockJumpIsNamedToo) {
  testing::TempDir dir;
  const std::string path = dir.file("clocks.bag");
  {
    rosbag::Bag bag(path, rosbag::bagmode::Write);
    for (int i = 0; i < 20; ++i) {
      const double t = kT0 + 0.1 * i;
      bag.write("/velodyne_points", testing::rosTime(t + 0.104),
                testing::velodyneCloud(i >= 10 ? t + 30.0 : t, sweep(80 + i, false)));
      bag.write("/mono", testing::rosTime(t + 0.003), testing::rawImage(t, randomImage(CV_8UC1, i), "mono8"));
    }
  }
  const std::string message = testing::errorMessageOf([&] { readAll(path); });
  EXPECT_NE(message.find(path + " topic /velodyne_points: time stamp "), std::string::npos) << message;
  EXPECT_NE(message.find("jumps by +30.000 s"), std::string::npos) << message;
}

TEST(RosbagClocks, ADropOutIsNoClockJump) {
  testing::TempDir dir;
  EXPECT_EQ(readAll(writeTwoClockBag(dir, 1000, 0.0, 0.5, 1.5)), 20u + 15u);  // 15 images outside the gap
}

}  // namespace
}  // namespace lvslam
