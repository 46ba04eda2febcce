// The saved map file: what is written reads back to the same map and, written
// again, to the same bytes; a foreign, newer, cut or damaged file is an
// lvslam::Error naming it.
#include "lvslam/system/saved_map.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <gtest/gtest.h>
#include <zlib.h>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"

namespace lvslam::system {
namespace {

std::string scratch(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("lvslam_saved_map_" + name)).string();
}

std::string bytesOf(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const std::string& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

SavedMap someMap() {
  SavedMap map;
  for (int k = 0; k < 3; ++k) {
    loop::LoopKeyframe kf;
    kf.t = 1700000000.0 + 0.7 * k;
    kf.path_length = 1.25 * k;
    kf.T_odom_lidar = makePose(expSO3(Eigen::Vector3d(0.1 * k, -0.2, 0.3 * k)), Eigen::Vector3d(k, -2.0 * k, 0.5));
    for (int i = 0; i < 5 + k; ++i) {
      lidar::FeaturePoint fp;
      fp.p = Eigen::Vector3f(0.1f * i, -3.0f + i, 1.0f / (1 + i));
      fp.direction = Eigen::Vector3f(0.0f, 0.6f, 0.8f);
      fp.time = 0.01f * i;
      fp.cls = static_cast<lidar::FeatureClass>(i % lidar::kFeatureClassCount);
      fp.refined = i % 2 == 1;
      kf.points.push_back(fp);
    }
    map.keyframes.push_back(kf);
  }
  const PlySegment s{Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d(-1.0, 0.5, 2.0), 255, 160, 0};
  map.lines = {s, s};
  map.lines[1].a.x() = 7.5;
  return map;
}

TEST(SavedMap, ReadsBackTheSameMapAndWritesTheSameBytes) {
  const SavedMap map = someMap();
  const std::string first = scratch("first.lvmap"), second = scratch("second.lvmap");
  writeSavedMap(first, map);
  const SavedMap read = readSavedMap(first);
  ASSERT_EQ(read.keyframes.size(), map.keyframes.size());
  for (std::size_t k = 0; k < map.keyframes.size(); ++k) {
    const loop::LoopKeyframe &a = map.keyframes[k], &b = read.keyframes[k];
    EXPECT_EQ(a.t, b.t);
    EXPECT_EQ(a.path_length, b.path_length);
    EXPECT_TRUE(a.T_odom_lidar.matrix() == b.T_odom_lidar.matrix());
    ASSERT_EQ(a.points.size(), b.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i) {
      EXPECT_TRUE(a.points[i].p == b.points[i].p);
      EXPECT_TRUE(a.points[i].direction == b.points[i].direction);
      EXPECT_EQ(a.points[i].time, b.points[i].time);
      EXPECT_EQ(a.points[i].cls, b.points[i].cls);
      EXPECT_EQ(a.points[i].refined, b.points[i].refined);
    }
  }
  ASSERT_EQ(read.lines.size(), 2u);
  EXPECT_TRUE(read.lines[1].a == map.lines[1].a);
  EXPECT_TRUE(read.lines[0].b == map.lines[0].b);
  EXPECT_EQ(read.lines[0].g, 160);
  writeSavedMap(second, read);
  EXPECT_EQ(bytesOf(first), bytesOf(second));
  std::remove(first.c_str());
  std::remove(second.c_str());
}

// The message of readSavedMap's error on `bytes`.
std::string errorOn(const std::string& name, const std::string& bytes) {
  const std::string path = scratch(name);
  writeBytes(path, bytes);
  try {
    readSavedMap(path);
  } catch (const Error& e) {
    std::remove(path.c_str());
    EXPECT_EQ(e.where(), path);
    return e.why();
  }
  std::remove(path.c_str());
  return "no error";
}

// The header: the 11-byte tag, the version (4), the payload's size (8) and CRC-32 (4).
constexpr std::size_t kHeader = 11 + 4 + 8 + 4;

// `bytes` with its header's CRC made to match the payload again: a value
// damaged this way passes the checksum and must be caught by the checks.
std::string withMatchingCrc(std::string bytes) {
  const std::uint32_t crc = static_cast<std::uint32_t>(
      crc32_z(0L, reinterpret_cast<const Bytef*>(bytes.data() + kHeader), bytes.size() - kHeader));
  std::memcpy(bytes.data() + kHeader - 4, &crc, sizeof(crc));
  return bytes;
}

TEST(SavedMap, AForeignNewerCutOrDamagedFileIsAnErrorNamingIt) {
  const std::string path = scratch("good.lvmap");
  writeSavedMap(path, someMap());
  const std::string good = bytesOf(path);
  std::remove(path.c_str());
  EXPECT_NE(errorOn("ply.lvmap", "ply\nformat ascii 1.0\n").find("not an lvslam map"), std::string::npos);
  EXPECT_NE(errorOn("empty.lvmap", "").find("not an lvslam map"), std::string::npos);
  std::string newer = good;
  newer[11] = 2;  // the version, after the tag
  EXPECT_NE(errorOn("newer.lvmap", newer).find("map format version 2; this lvslam reads version 1"), std::string::npos);
  EXPECT_NE(errorOn("header.lvmap", good.substr(0, 14)).find("cut short in its header"), std::string::npos);
  EXPECT_NE(errorOn("cut.lvmap", good.substr(0, good.size() - 9)).find("cut short or damaged"), std::string::npos);
  std::string flipped = good;
  flipped[kHeader + 40] ^= 0x10;  // one bit of the first keyframe's pose
  EXPECT_NE(errorOn("flipped.lvmap", flipped).find("checksum does not match"), std::string::npos);
  // The first point's class byte: after the keyframe count (8), the first
  // keyframe's t and path (16) and pose (128), its point count (8) and the
  // point's p, direction and time (28).
  const std::size_t cls = kHeader + 8 + 16 + 128 + 8 + 28;
  ASSERT_EQ(good[cls], 0);
  std::string bad_class = good;
  bad_class[cls] = 9;
  EXPECT_NE(errorOn("class.lvmap", withMatchingCrc(bad_class)).find("class 9"), std::string::npos);
  std::string bad_flag = good;
  bad_flag[cls + 1] = 7;
  EXPECT_NE(errorOn("flag.lvmap", withMatchingCrc(bad_flag)).find("flag 7"), std::string::npos);
  std::string far_point = good;
  const float far = 3e8f;  // the first point's x: beyond any sensor's reach
  std::memcpy(far_point.data() + cls - 28, &far, sizeof(far));
  EXPECT_NE(errorOn("far.lvmap", withMatchingCrc(far_point)).find("out of range"), std::string::npos);
  std::string bad_pose = good;
  bad_pose[kHeader + 8 + 16 + 7] = '\x7f';  // the first pose's first entry's top byte: no longer a rotation
  EXPECT_NE(errorOn("pose.lvmap", withMatchingCrc(bad_pose)).find("not a finite rigid pose"), std::string::npos);
  std::string huge_count = good;
  huge_count[kHeader + 7] = '\x7f';  // the keyframe count's top byte
  EXPECT_NE(errorOn("count.lvmap", withMatchingCrc(huge_count)).find("not a valid map"), std::string::npos);
}

TEST(SavedMap, AMissingFileOrFolderIsAnErrorNamingIt) {
  const std::string path = scratch("missing_dir/never.lvmap");
  try {
    readSavedMap(path);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), path);
    EXPECT_NE(e.why().find("cannot read the map"), std::string::npos);
  }
  try {
    writeSavedMap(path, someMap());
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), path);
  }
}

}  // namespace
}  // namespace lvslam::system
