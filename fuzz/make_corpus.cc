// Writes the seed corpus of every fuzz harness (fuzz/corpus/<name>/) with the
// project's own writers: fuzz_make_corpus <fuzz/corpus>. Seeds are small
// (a few points, a few poses, tiny images), so the fuzzer mutates structure,
// not bulk. The corpus is kept in the repository; run this again only when a
// format changes.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "io/rosbag_test_messages.h"  // tests/: messages built field by field, rosbag::Bag
#include "lvslam/eval/json_writer.h"
#include "lvslam/io/ply_writer.h"
#include "lvslam/io/scan_file.h"
#include "lvslam/io/sequence_info.h"
#include "lvslam/io/tum.h"
#include "lvslam/system/saved_map.h"

namespace {

namespace fs = std::filesystem;
using lvslam::testing::VelodynePoint;

void writeBytes(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << bytes;
}

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

template <class Message>
std::string serialized(const Message& message) {
  std::string bytes(ros::serialization::serializationLength(message), '\0');
  ros::serialization::OStream stream(reinterpret_cast<std::uint8_t*>(bytes.data()), static_cast<std::uint32_t>(bytes.size()));
  ros::serialization::serialize(stream, message);
  return bytes;
}

std::string encoded(const std::string& extension, const cv::Mat& image) {
  std::vector<std::uint8_t> bytes;
  cv::imencode(extension, image, bytes);
  return {bytes.begin(), bytes.end()};
}

cv::Mat gradient(int rows, int cols, int type) {
  cv::Mat image(rows, cols, type);
  cv::randu(image, cv::Scalar::all(0), cv::Scalar::all(type == CV_16UC1 ? 65535 : 255));
  return image;
}

std::vector<VelodynePoint> sweepPoints(bool end_stamped) {
  std::vector<VelodynePoint> points;
  for (int i = 0; i < 4; ++i) {
    const float a = 0.5f * static_cast<float>(i);
    const float t = 0.025f * static_cast<float>(i) - (end_stamped ? 0.1f : 0.0f);
    points.push_back({5.0f * std::cos(a), 5.0f * std::sin(a), -0.5f + 0.1f * i, 10.0f * i,
                      static_cast<std::uint16_t>(i), t});
  }
  return points;
}

lvslam::SequenceInfo sequenceInfo(bool with_camera) {
  lvslam::SequenceInfo info;
  info.name = "room \"seed\"";
  if (with_camera) {
    lvslam::CameraInfo camera;
    camera.camera = lvslam::PinholeCamera(64, 48, 50.0, 50.0, 32.0, 24.0);
    camera.rate_hz = 15.0;
    info.camera = camera;
    info.groundtruth_frame = lvslam::GroundTruthFrame::kCamera;
  }
  lvslam::LidarInfo lidar;
  lidar.rings = 16;
  lidar.rate_hz = 10.0;
  info.lidar = lidar;
  info.T_camera_lidar.translation() = Eigen::Vector3d(0.1, -0.05, 0.02);
  return info;
}

void writeYamlSeeds(const fs::path& corpus, const fs::path& config_dir) {
  lvslam::writeSequenceInfo((corpus / "sequence_yaml" / "camera_lidar.yaml").string(), sequenceInfo(true));
  lvslam::writeSequenceInfo((corpus / "sequence_yaml" / "lidar_only.yaml").string(), sequenceInfo(false));
  writeBytes(corpus / "sensor_preset" / "m2dgr.yaml", slurp(config_dir / "m2dgr.yaml"));
  writeBytes(corpus / "sensor_preset" / "lidar_only.yaml",
             "format: lvslam-preset/1\nname: rig\ntopics:\n  lidar: /points\nlidar:\n  rings: 16\n");
  writeBytes(corpus / "config_yaml" / "sim.yaml", slurp(config_dir / "sim.yaml"));
  writeBytes(corpus / "config_yaml" / "advanced.yaml", slurp(config_dir / "advanced.yaml"));
  writeBytes(corpus / "config_yaml" / "estimator.yaml",
             "estimator:\n  window_s: 1.0\n  huber_delta: 2.0\nsystem:\n  keypoint_depth_source: features\n"
             "  map_voxel: 0.1\ndetection:\n  min_tracked_points: 30\n");
}

void writeTextSeeds(const fs::path& corpus) {
  lvslam::eval::JsonObject accuracy, summary, frame, stats;
  accuracy.addString("align", "se3").addNumber("ate_rmse", 0.0123).addNumber("nan", std::nan(""));
  summary.addRaw("accuracy", accuracy.str()).addCount("frames", 2).addString("mode", "fused \"q\"\n\u00e9");
  frame.addNumber("t", 1700000000.066666667).addRaw("features", lvslam::eval::jsonArray({1, 2.5e-7, -3e300}));
  stats.addRaw("summary", summary.str()).addRaw("frames", "[" + frame.str() + "]").addRaw("scans", "[]")
      .addRaw("switches", "[]");
  writeBytes(corpus / "json" / "stats.json", stats.str());
  writeBytes(corpus / "times_file" / "camera.txt", "1700000000.000000000 0.png\n1700000000.066666667 1.png\n");
  writeBytes(corpus / "times_file" / "comments.txt", "# t file\n\n12.5 0.bin\n");
  lvslam::Trajectory trajectory;
  for (int i = 0; i < 3; ++i) {
    Eigen::Isometry3d T_world_frame = Eigen::Isometry3d::Identity();
    T_world_frame.linear() = Eigen::AngleAxisd(0.1 * i, Eigen::Vector3d::UnitZ()).toRotationMatrix();
    T_world_frame.translation() = Eigen::Vector3d(0.5 * i, 0.1 * i, 0.0);
    trajectory.push_back({1700000000.0 + 0.1 * i, T_world_frame});
  }
  lvslam::writeTum((corpus / "tum" / "three_poses.tum").string(), trajectory);
  writeBytes(corpus / "kitti_poses" / "poses.txt",
             "1 0 0 0 0 1 0 0 0 0 1 0\n0.995 -0.0998 0 0.5 0.0998 0.995 0 0.1 0 0 1 0\n");
  writeBytes(corpus / "kitti_poses" / "poses_and_times.txt",
             "1 0 0 0 0 1 0 0 0 0 1 0\n1 0 0 1 0 1 0 0 0 0 1 0\n--- times\n0.0\n1.0e-1\n");
}

// The ply harness's first byte: 0 reads a point cloud, 1 line segments.
void writePlySeeds(const fs::path& corpus, const fs::path& scratch) {
  const std::vector<lvslam::PlyPoint> points = {{{1.0f, 2.0f, -0.5f}, 0.25f}, {{-3.0f, 0.5f, 1.5f}, 1.0f}};
  lvslam::writePointCloudPly((scratch / "lvslam-corpus-map.ply").string(), points);
  writeBytes(corpus / "ply" / "map.ply", std::string(1, '\0') + slurp(scratch / "lvslam-corpus-map.ply"));
  lvslam::PlySegment segment;
  segment.a = {0.0, 1.0, 2.0};
  segment.b = {1.5, -1.0, 2.5};
  lvslam::writeLineSegmentsPly((scratch / "lvslam-corpus-lines.ply").string(), {segment, segment});
  writeBytes(corpus / "ply" / "lines.ply", std::string(1, '\1') + slurp(scratch / "lvslam-corpus-lines.ply"));
  fs::remove(scratch / "lvslam-corpus-map.ply");
  fs::remove(scratch / "lvslam-corpus-lines.ply");
}

void writeScanSeeds(const fs::path& corpus) {
  // The harness's first bytes: the field count (3 + b % 6), then each field's
  // index in its name list (x y z intensity time ring pad tiem).
  const std::vector<std::pair<std::string, std::string>> layouts = {
      {"xyzitr", std::string{3, 0, 1, 2, 3, 4, 5}}, {"xyz", std::string{0, 0, 1, 2}},
      {"xyz_pad_i", std::string{2, 0, 1, 2, 6, 3}}};
  lvslam::LidarScan scan;
  for (const VelodynePoint& v : sweepPoints(false)) {
    lvslam::LidarPoint p;
    p.p = {v.x, v.y, v.z};
    p.intensity = v.intensity;
    p.time = v.time;
    p.ring = v.ring;
    scan.points.push_back(p);
  }
  const std::vector<std::string> names = {"x", "y", "z", "intensity", "time", "ring", "pad", "tiem"};
  for (const auto& [name, header] : layouts) {
    std::vector<std::string> fields;
    for (std::size_t i = 1; i < header.size(); ++i) fields.push_back(names[header[i]]);
    const fs::path scan_path = corpus / "scan_file" / (name + ".scan");
    lvslam::writeScanFile(scan_path.string(), fields, scan);
    writeBytes(scan_path, header + slurp(scan_path));
  }
}

void writeRosSeeds(const fs::path& corpus) {
  using lvslam::testing::compressedImage;
  using lvslam::testing::rawImage;
  using lvslam::testing::velodyneCloud;
  writeBytes(corpus / "pointcloud2" / "start_stamped.msg", serialized(velodyneCloud(1700000000.0, sweepPoints(false))));
  writeBytes(corpus / "pointcloud2" / "end_stamped.msg", serialized(velodyneCloud(1700000000.1, sweepPoints(true))));

  const cv::Mat gray = gradient(6, 8, CV_8UC1), colour = gradient(4, 4, CV_8UC3);
  writeBytes(corpus / "png_image" / "gray.png", encoded(".png", gray));
  writeBytes(corpus / "png_image" / "colour.png", encoded(".png", colour));
  writeBytes(corpus / "png_image" / "depth16.png", encoded(".png", gradient(3, 5, CV_16UC1)));

  writeBytes(corpus / "ros_image" / "mono8.msg", std::string(1, '\0') + serialized(rawImage(1.0, gray, "mono8")));
  writeBytes(corpus / "ros_image" / "rgb8.msg", std::string(1, '\0') + serialized(rawImage(1.0, colour, "rgb8")));
  writeBytes(corpus / "ros_image" / "png.msg",
             std::string(1, '\1') + serialized(compressedImage(1.0, [&] {
               const std::string png = encoded(".png", gray);
               return std::vector<std::uint8_t>(png.begin(), png.end());
             }(), "png")));
  writeBytes(corpus / "ros_image" / "jpeg.msg",
             std::string(1, '\1') + serialized(compressedImage(1.0, [&] {
               const std::string jpeg = encoded(".jpg", colour);
               return std::vector<std::uint8_t>(jpeg.begin(), jpeg.end());
             }(), "bgr8; jpeg compressed bgr8")));

  // Bags of one cloud and one image, in each chunk compression.
  const std::vector<std::pair<std::string, rosbag::CompressionType>> compressions = {
      {"none", rosbag::compression::Uncompressed}, {"lz4", rosbag::compression::LZ4}, {"bz2", rosbag::compression::BZ2}};
  for (const auto& [name, compression] : compressions) {
    const fs::path path = corpus / "bag_records" / (name + ".bag");
    rosbag::Bag bag(path.string(), rosbag::bagmode::Write);
    bag.setCompression(compression);
    bag.write("/points", lvslam::testing::rosTime(1.05), velodyneCloud(1.0, sweepPoints(false)));
    bag.write("/image", lvslam::testing::rosTime(1.06), rawImage(1.0, gray, "mono8"));
  }
}

// Saved maps (lvslam run --map-out): two keyframes of a few points and a
// line; no keyframe at all.
void writeSavedMapSeeds(const fs::path& corpus) {
  lvslam::system::SavedMap map;
  for (int k = 0; k < 2; ++k) {
    lvslam::loop::LoopKeyframe keyframe;
    keyframe.t = 1700000000.0 + k;
    keyframe.path_length = 1.0 * k;
    keyframe.T_odom_lidar.translation() = Eigen::Vector3d(1.0 * k, 0.5, 0.0);
    for (int i = 0; i < 3; ++i) {
      lvslam::lidar::FeaturePoint point;
      point.p = Eigen::Vector3f(1.0f + i, -2.0f, 0.5f * i);
      point.cls = static_cast<lvslam::lidar::FeatureClass>(i);
      point.refined = i == 1;
      keyframe.points.push_back(point);
    }
    map.keyframes.push_back(keyframe);
  }
  map.lines.push_back({Eigen::Vector3d(0.0, 0.0, 1.0), Eigen::Vector3d(1.0, 0.0, 1.0), 0, 255, 0});
  // The harness's first byte: 0 makes the CRC match whatever follows, 1 keeps it as written.
  const fs::path scratch = fs::temp_directory_path() / "lvslam-corpus.lvmap";
  lvslam::system::writeSavedMap(scratch.string(), map);
  writeBytes(corpus / "saved_map" / "two_keyframes.lvmap", std::string(1, '\0') + slurp(scratch));
  writeBytes(corpus / "saved_map" / "two_keyframes_as_is.lvmap", std::string(1, '\1') + slurp(scratch));
  lvslam::system::writeSavedMap(scratch.string(), {});
  writeBytes(corpus / "saved_map" / "empty.lvmap", std::string(1, '\0') + slurp(scratch));
  fs::remove(scratch);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: fuzz_make_corpus <fuzz/corpus> <config folder>\n";
    return 2;
  }
  const fs::path corpus = argv[1];
  for (const char* name : {"sequence_yaml", "sensor_preset", "config_yaml", "times_file", "scan_file", "tum",
                           "kitti_poses", "json", "ply", "pointcloud2", "png_image", "ros_image", "bag_records",
                           "saved_map"})
    fs::create_directories(corpus / name);
  writeYamlSeeds(corpus, argv[2]);
  writeTextSeeds(corpus);
  writeScanSeeds(corpus);
  writePlySeeds(corpus, fs::temp_directory_path());
  writeRosSeeds(corpus);
  writeSavedMapSeeds(corpus);
  std::cout << "seed corpus written to " << corpus.string() << "\n";
  return 0;
}
