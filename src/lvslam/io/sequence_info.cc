#include "lvslam/io/sequence_info.h"

#include <algorithm>
#include <array>
#include <fstream>
#include <set>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"
#include "lvslam/core/yaml_config.h"

namespace lvslam {

CameraInfo parseCameraInfo(const YamlConfig& node) {
  const std::string model = node.getString("model", "pinhole");
  if (model != "pinhole") node.at("model").fail("unsupported model '" + model + "' (only pinhole)");
  const int width = node.at("width").asInt();
  const int height = node.at("height").asInt();
  if (width <= 0) node.at("width").fail("must be positive");
  if (height <= 0) node.at("height").fail("must be positive");
  const YamlConfig intr = node.at("intrinsics");
  const std::vector<double> k = intr.asDoubles();
  if (k.size() != 4) intr.fail(fmt::format("expected 4 numbers [fx, fy, cx, cy], got {}", k.size()));
  if (!(k[0] > 0.0) || !(k[1] > 0.0)) intr.fail("fx and fy must be positive");

  RadTanDistortion dist;
  if (const auto d = node.find("distortion")) {
    const std::string dmodel = d->at("model").asString();
    if (dmodel != "radtan") d->at("model").fail("unsupported distortion model '" + dmodel + "' (only radtan)");
    const YamlConfig coeffs_node = d->at("coeffs");
    const std::vector<double> c = coeffs_node.asDoubles();
    if (c.size() != 4 && c.size() != 5)
      coeffs_node.fail(fmt::format("expected 5 numbers [k1, k2, p1, p2, k3], got {}", c.size()));
    dist = {c[0], c[1], c[2], c[3], c.size() == 5 ? c[4] : 0.0};
  }
  return {PinholeCamera(width, height, k[0], k[1], k[2], k[3], dist), node.getDouble("rate_hz", 0.0)};
}

namespace {

LidarInfo parseLidar(const YamlConfig& node) {
  LidarInfo info;
  info.rings = node.getInt("rings", 0);
  info.rate_hz = node.getDouble("rate_hz", 0.0);
  const YamlConfig fields = node.at("point_fields");
  info.point_fields = fields.asStrings();
  std::set<std::string> seen;
  for (const auto& f : info.point_fields)
    if (!seen.insert(f).second) fields.fail("field '" + f + "' appears twice");
  for (const char* required : {"x", "y", "z"})
    if (!seen.count(required)) fields.fail(std::string("must contain '") + required + "'");
  const std::string ref = node.getString("time_reference", "start");
  if (ref == "start") {
    info.time_reference = TimeReference::kStart;
  } else if (ref == "end") {
    info.time_reference = TimeReference::kEnd;
  } else {
    node.at("time_reference").fail("expected 'start' or 'end', got '" + ref + "'");
  }
  return info;
}

}  // namespace

Eigen::Isometry3d parseTransformMatrix(const YamlConfig& node) {
  const std::vector<double> m = node.asDoubles();
  if (m.size() != 16) node.fail(fmt::format("expected 16 numbers (row-major 4x4), got {}", m.size()));
  Eigen::Matrix4d M;
  for (int i = 0; i < 16; ++i) M(i / 4, i % 4) = m[i];
  if (M(3, 0) != 0.0 || M(3, 1) != 0.0 || M(3, 2) != 0.0 || M(3, 3) != 1.0)
    node.fail("last row must be [0, 0, 0, 1]");
  if (!isRotation(M.topLeftCorner<3, 3>(), 1e-3)) node.fail("rotation part is not a rotation (tolerance 1e-3)");
  // Within tolerance: snap to the nearest rotation so later maths stays exact.
  return makePose(closestRotation(M.topLeftCorner<3, 3>()), M.topRightCorner<3, 1>());
}

void requireFormat(const YamlConfig& root, const char* expected) {
  const std::string format = root.at("format").asString();
  if (format != expected) root.at("format").fail(fmt::format("expected '{}', got '{}'", expected, format));
}

GroundTruthFrame parseGroundTruthFrame(const YamlConfig& frame) {
  const std::string name = frame.asString();
  if (name == "camera") return GroundTruthFrame::kCamera;
  if (name != "lidar") frame.fail("expected 'camera' or 'lidar', got '" + name + "'");
  return GroundTruthFrame::kLidar;
}

Calibration calibrationOf(const std::optional<CameraInfo>& camera, const Eigen::Isometry3d& T_camera_lidar) {
  Calibration c;
  if (camera) c.camera = camera->camera;
  c.T_camera_lidar = T_camera_lidar;
  return c;
}

Calibration SequenceInfo::calibration() const { return calibrationOf(camera, T_camera_lidar); }

SequenceInfo readSequenceInfo(const std::string& yaml_path) {
  const YamlConfig root = YamlConfig::loadFile(yaml_path);
  requireFormat(root, kSequenceFormat);
  SequenceInfo info;
  info.name = root.getString("name", "");
  if (const auto cam = root.find("camera")) info.camera = parseCameraInfo(*cam);
  if (const auto lidar = root.find("lidar")) info.lidar = parseLidar(*lidar);
  if (!info.camera && !info.lidar) root.fail("the sequence has neither 'camera' nor 'lidar'");
  if (const auto ext = root.find("extrinsics")) {
    info.T_camera_lidar = parseTransformMatrix(ext->at("T_camera_lidar"));
  } else if (info.camera && info.lidar) {
    root.at("extrinsics");  // throws: a camera and a LiDAR need their extrinsics
  }
  if (const auto gt = root.find("groundtruth")) info.groundtruth_frame = parseGroundTruthFrame(gt->at("frame"));
  return info;
}

// Through yaml-cpp's emitter, so that any name (quotes, backslashes,
// unicode) reads back as written; doubles with 17 digits read back exactly.
void writeSequenceInfo(const std::string& yaml_path, const SequenceInfo& info) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "format" << YAML::Value << std::string(kSequenceFormat);
  out << YAML::Key << "name" << YAML::Value << YAML::DoubleQuoted << info.name;
  const auto flowList = [&out](const auto& values) {
    out << YAML::Flow << YAML::BeginSeq;
    for (const auto& v : values) out << v;
    out << YAML::EndSeq;
  };
  if (info.camera) {
    const PinholeCamera& c = info.camera->camera;
    out << YAML::Key << "camera" << YAML::Value << YAML::BeginMap;
    out << YAML::Key << "model" << YAML::Value << "pinhole";
    out << YAML::Key << "width" << YAML::Value << c.width();
    out << YAML::Key << "height" << YAML::Value << c.height();
    out << YAML::Key << "intrinsics" << YAML::Value;
    flowList(std::array<double, 4>{c.fx(), c.fy(), c.cx(), c.cy()});
    if (c.isDistorted()) {
      const RadTanDistortion& d = c.distortion();
      out << YAML::Key << "distortion" << YAML::Value << YAML::BeginMap;
      out << YAML::Key << "model" << YAML::Value << "radtan";
      out << YAML::Key << "coeffs" << YAML::Value;
      flowList(std::array<double, 5>{d.k1, d.k2, d.p1, d.p2, d.k3});
      out << YAML::EndMap;
    }
    if (info.camera->rate_hz > 0.0) out << YAML::Key << "rate_hz" << YAML::Value << info.camera->rate_hz;
    out << YAML::EndMap;
  }
  if (info.lidar) {
    const LidarInfo& l = *info.lidar;
    out << YAML::Key << "lidar" << YAML::Value << YAML::BeginMap;
    if (l.rings > 0) out << YAML::Key << "rings" << YAML::Value << l.rings;
    if (l.rate_hz > 0.0) out << YAML::Key << "rate_hz" << YAML::Value << l.rate_hz;
    out << YAML::Key << "point_fields" << YAML::Value;
    flowList(l.point_fields);
    out << YAML::Key << "time_reference" << YAML::Value
        << (l.time_reference == TimeReference::kStart ? "start" : "end");
    out << YAML::EndMap;
  }
  const Eigen::Matrix4d M = info.T_camera_lidar.matrix();
  std::array<double, 16> row_major{};
  for (int i = 0; i < 16; ++i) row_major[static_cast<std::size_t>(i)] = M(i / 4, i % 4);
  out << YAML::Key << "extrinsics" << YAML::Value << YAML::BeginMap << YAML::Key << "T_camera_lidar" << YAML::Value;
  flowList(row_major);
  out << YAML::EndMap;
  if (info.groundtruth_frame)
    out << YAML::Key << "groundtruth" << YAML::Value << YAML::BeginMap << YAML::Key << "frame" << YAML::Value
        << (*info.groundtruth_frame == GroundTruthFrame::kCamera ? "camera" : "lidar") << YAML::EndMap;
  out << YAML::EndMap;
  if (!out.good()) throw Error(yaml_path, "cannot emit YAML: " + out.GetLastError());
  std::ofstream file(yaml_path);
  if (!file) throw Error(yaml_path, "cannot write file");
  file << out.c_str() << "\n";
  if (!file) throw Error(yaml_path, "write failed");
}

}  // namespace lvslam
