#include "lvslam/system/saved_map.h"

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <fmt/format.h>
#include <zlib.h>

#include "lvslam/core/error.h"
#include "lvslam/system/record_file.h"

namespace lvslam::system {

namespace {

constexpr std::string_view kTag = "LVSLAM-MAP\n";
// Bounds no real map reaches: a feature point's range in its scan (the
// sensor's reach), a direction's length, a point's time in its sweep, a
// keyframe's distance from the map's origin.
constexpr float kMaxPointRange = 1e4f;    // metres
constexpr double kMaxMapExtent = 1e7;     // metres
constexpr float kMaxPointTime = 10.0f;    // seconds

std::uint32_t crc32Of(std::string_view bytes) {
  return static_cast<std::uint32_t>(crc32_z(0L, reinterpret_cast<const Bytef*>(bytes.data()), bytes.size()));
}

// What the file holds, in plain fields: flags and classes as bytes, so that
// a damaged byte is a value to reject, not an invalid bool or enum.
struct MapPoint {
  Eigen::Vector3f p = Eigen::Vector3f::Zero();
  Eigen::Vector3f direction = Eigen::Vector3f::UnitZ();
  float time = 0.0f;
  std::uint8_t cls = 0, refined = 0;
};
struct MapKeyframe {
  double t = 0.0, path_length = 0.0;
  Eigen::Isometry3d T_map_lidar = Eigen::Isometry3d::Identity();
  std::vector<MapPoint> points;
};
struct MapLine {
  Eigen::Vector3d a = Eigen::Vector3d::Zero(), b = Eigen::Vector3d::Zero();
  std::uint8_t r = 0, g = 0, blue = 0;
};
struct MapPayload {
  std::vector<MapKeyframe> keyframes;
  std::vector<MapLine> lines;
};

template <typename A>
void fields(A& a, MapPoint& p) {
  a(p.p), a(p.direction), a(p.time), a(p.cls), a(p.refined);
}
template <typename A>
void fields(A& a, MapKeyframe& k) {
  a(k.t), a(k.path_length), a(k.T_map_lidar), a(k.points);
}
template <typename A>
void fields(A& a, MapLine& l) {
  a(l.a), a(l.b), a(l.r), a(l.g), a(l.blue);
}
template <typename A>
void fields(A& a, MapPayload& m) {
  a(m.keyframes), a(m.lines);
}

MapPayload payloadOf(const SavedMap& map) {
  MapPayload payload;
  for (const loop::LoopKeyframe& kf : map.keyframes) {
    MapKeyframe k{kf.t, kf.path_length, kf.T_odom_lidar, {}};
    k.points.reserve(kf.points.size());
    for (const lidar::FeaturePoint& fp : kf.points)
      k.points.push_back({fp.p, fp.direction, fp.time, static_cast<std::uint8_t>(fp.cls),
                          static_cast<std::uint8_t>(fp.refined ? 1 : 0)});
    payload.keyframes.push_back(std::move(k));
  }
  for (const PlySegment& s : map.lines) payload.lines.push_back({s.a, s.b, s.r, s.g, s.b_colour});
  return payload;
}

bool isRotation(const Eigen::Matrix3d& R) {
  return R.allFinite() && (R.transpose() * R - Eigen::Matrix3d::Identity()).norm() < 1e-6 && R.determinant() > 0.0;
}

SavedMap mapOf(const MapPayload& payload, const std::string& path) {
  const auto bad = [&path](const std::string& what) { return Error(path, "not a valid map: " + what); };
  SavedMap map;
  for (std::size_t i = 0; i < payload.keyframes.size(); ++i) {
    const MapKeyframe& k = payload.keyframes[i];
    const Eigen::Matrix4d& M = k.T_map_lidar.matrix();
    if (!std::isfinite(k.t) || !std::isfinite(k.path_length) || !M.allFinite() ||
        !isRotation(k.T_map_lidar.linear()) || M.row(3) != Eigen::RowVector4d(0, 0, 0, 1) ||
        !(k.T_map_lidar.translation().norm() < kMaxMapExtent))
      throw bad(fmt::format("keyframe {}: its time, path or pose is not a finite rigid pose", i));
    loop::LoopKeyframe kf{k.t, k.T_map_lidar, {}, k.path_length};
    kf.points.reserve(k.points.size());
    for (const MapPoint& p : k.points) {
      const float direction = p.direction.norm();
      if (p.cls >= lidar::kFeatureClassCount || p.refined > 1 || !(p.p.norm() < kMaxPointRange) ||
          !(direction > 0.5f && direction < 2.0f) || !(std::abs(p.time) < kMaxPointTime))
        throw bad(fmt::format("keyframe {}: a feature point with class {}, flag {} or a value out of range", i,
                              static_cast<int>(p.cls), static_cast<int>(p.refined)));
      kf.points.push_back({p.p, p.direction, p.time, static_cast<lidar::FeatureClass>(p.cls), p.refined == 1});
    }
    map.keyframes.push_back(std::move(kf));
  }
  for (const MapLine& l : payload.lines) {
    if (!(l.a.norm() < kMaxMapExtent) || !(l.b.norm() < kMaxMapExtent)) throw bad("a line end out of range");
    map.lines.push_back({l.a, l.b, l.r, l.g, l.blue});
  }
  return map;
}

}  // namespace

SavedMap savedMapOf(std::vector<loop::LoopKeyframe> keyframes, const std::optional<loop::LoopClosureResult>& loop,
                    std::vector<PlySegment> lines) {
  // The graph's poses (in fused mode on the fused trajectory, the lines' frame), corrected when it solved.
  if (loop && loop->T_odom_lidar.size() == keyframes.size()) {
    const std::vector<Eigen::Isometry3d>& poses = loop->solved ? loop->T_odom_lidar_corrected : loop->T_odom_lidar;
    for (std::size_t k = 0; k < keyframes.size(); ++k) keyframes[k].T_odom_lidar = poses[k];
  }
  return {std::move(keyframes), std::move(lines)};
}

// Written beside the file and renamed over it: a failure leaves an earlier
// map of that name as it was.
void writeSavedMap(const std::string& path, const SavedMap& map) {
  RecordWriter writer;
  writer(payloadOf(map));
  const std::string partial = path + ".partial";
  std::ofstream out(partial, std::ios::binary | std::ios::trunc);
  if (!out) throw Error(path, "cannot write the map");
  const std::uint32_t version = kSavedMapVersion;
  const std::uint64_t size = writer.bytes().size();
  const std::uint32_t crc = crc32Of(writer.bytes());
  out.write(kTag.data(), static_cast<std::streamsize>(kTag.size()));
  out.write(reinterpret_cast<const char*>(&version), sizeof(version));
  out.write(reinterpret_cast<const char*>(&size), sizeof(size));
  out.write(reinterpret_cast<const char*>(&crc), sizeof(crc));
  out.write(writer.bytes().data(), static_cast<std::streamsize>(size));
  out.close();
  std::error_code ec;
  if (!out) {
    std::filesystem::remove(partial, ec);
    throw Error(path, "cannot write the map");
  }
  std::filesystem::rename(partial, path, ec);
  if (ec) {
    std::filesystem::remove(partial, ec);
    throw Error(path, "cannot write the map: " + ec.message());
  }
}

SavedMap readSavedMap(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot read the map (missing or not readable)");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw Error(path, "cannot read the map");
  if (bytes.compare(0, kTag.size(), kTag) != 0) throw Error(path, "not an lvslam map (no LVSLAM-MAP tag)");
  std::uint32_t version = 0, crc = 0;
  std::uint64_t size = 0;
  const std::size_t header = kTag.size() + sizeof(version) + sizeof(size) + sizeof(crc);
  if (bytes.size() < header) throw Error(path, "the map is cut short in its header");
  std::memcpy(&version, bytes.data() + kTag.size(), sizeof(version));
  std::memcpy(&size, bytes.data() + kTag.size() + sizeof(version), sizeof(size));
  std::memcpy(&crc, bytes.data() + kTag.size() + sizeof(version) + sizeof(size), sizeof(crc));
  if (version != kSavedMapVersion)
    throw Error(path, fmt::format("map format version {}; this lvslam reads version {}", version, kSavedMapVersion));
  if (size != bytes.size() - header)
    throw Error(path, fmt::format("the map holds {} bytes after its header where it says {}: cut short or damaged",
                                  bytes.size() - header, size));
  const std::string_view payload_bytes = std::string_view(bytes).substr(header);
  if (crc32Of(payload_bytes) != crc) throw Error(path, "the map's checksum does not match: the file is damaged");
  MapPayload payload;
  try {
    RecordReader reader(payload_bytes);
    reader(payload);
    if (!reader.done()) throw Error(path, "not a valid map: bytes after its last field");
  } catch (const Error& e) {
    if (e.where() == path) throw;
    throw Error(path, std::string("not a valid map: ") + e.why());
  } catch (const std::bad_alloc&) {
    throw Error(path, "not a valid map: it asks for more memory than there is");
  }
  return mapOf(payload, path);
}

}  // namespace lvslam::system
