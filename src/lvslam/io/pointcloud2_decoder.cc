#include "lvslam/io/pointcloud2_decoder.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/io/rosbag_msgs.h"

namespace lvslam {

namespace {

// A point time this far on the wrong side of the stamp still counts as on
// its side (clock jitter between packets and header).
constexpr double kReferenceTolerance = 1e-3;

// sensor_msgs/PointField datatypes 1..8: INT8 UINT8 INT16 UINT16 INT32 UINT32 FLOAT32 FLOAT64.
int datatypeSize(std::uint8_t datatype) {
  static constexpr int kSizes[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};
  return datatype >= 1 && datatype <= 8 ? kSizes[datatype] : 0;
}

bool isFloatType(std::uint8_t datatype) { return datatype == 7 || datatype == 8; }

template <class T>
T load(const std::uint8_t* p, bool swap) {
  std::uint8_t bytes[sizeof(T)];
  std::memcpy(bytes, p, sizeof(T));
  if (swap) std::reverse(bytes, bytes + sizeof(T));
  T v;
  std::memcpy(&v, bytes, sizeof(T));
  return v;
}

struct FieldReader {
  std::uint32_t offset = 0;
  std::uint8_t datatype = 0;
  bool swap = false;

  double read(const std::uint8_t* point) const {
    const std::uint8_t* p = point + offset;
    switch (datatype) {
      case 1: return load<std::int8_t>(p, swap);
      case 2: return load<std::uint8_t>(p, swap);
      case 3: return load<std::int16_t>(p, swap);
      case 4: return load<std::uint16_t>(p, swap);
      case 5: return load<std::int32_t>(p, swap);
      case 6: return load<std::uint32_t>(p, swap);
      case 7: return load<float>(p, swap);
      case 8: return load<double>(p, swap);
      default: return std::numeric_limits<double>::quiet_NaN();
    }
  }
};

struct CloudLayout {
  FieldReader x, y, z;
  std::optional<FieldReader> intensity, ring, time, time_sec, time_nsec;
  std::uint32_t end = 0;  // bytes of a point that the fields use
};

std::optional<FieldReader> findField(const rosmsg::PointCloud2& cloud, const std::vector<std::string>& names,
                                     const std::string& where) {
  const bool swap = (cloud.is_bigendian != 0) != (std::endian::native == std::endian::big);
  for (const std::string& name : names) {
    for (const auto& f : cloud.fields) {
      if (std::string(f.name.c_str()) != name) continue;
      const int size = datatypeSize(f.datatype);
      if (size == 0)
        throw Error(where, fmt::format("PointCloud2 field '{}' has unknown datatype {}", name, f.datatype));
      if (static_cast<std::uint64_t>(f.offset) + size > cloud.point_step)
        throw Error(where, fmt::format("PointCloud2 field '{}' (offset {}, {} bytes) does not fit in point_step {}",
                                       name, f.offset, size, cloud.point_step));
      return FieldReader{f.offset, f.datatype, swap};
    }
  }
  return std::nullopt;
}

CloudLayout findLayout(const rosmsg::PointCloud2& cloud, const std::string& where) {
  CloudLayout layout;
  FieldReader* xyz[] = {&layout.x, &layout.y, &layout.z};
  const char* names[] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    const auto f = findField(cloud, {names[i]}, where);
    if (!f) {
      std::vector<std::string> present;
      for (const auto& pf : cloud.fields) present.emplace_back(pf.name.c_str());
      throw Error(where, fmt::format("PointCloud2 has no field '{}' (fields: {})", names[i], fmt::join(present, ", ")));
    }
    *xyz[i] = *f;
  }
  layout.intensity = findField(cloud, {"intensity"}, where);
  layout.ring = findField(cloud, {"ring", "laser_id"}, where);
  layout.time_sec = findField(cloud, {"time_sec"}, where);
  layout.time_nsec = findField(cloud, {"time_nsec"}, where);
  if (!layout.time_sec || !layout.time_nsec) {
    layout.time_sec.reset();
    layout.time_nsec.reset();
    layout.time = findField(cloud, {"time", "t", "timestamp"}, where);
  }
  for (const auto& f : {std::optional<FieldReader>(layout.x), std::optional<FieldReader>(layout.y),
                        std::optional<FieldReader>(layout.z), layout.intensity, layout.ring, layout.time,
                        layout.time_sec, layout.time_nsec})
    if (f) layout.end = std::max<std::uint32_t>(layout.end, f->offset + datatypeSize(f->datatype));
  return layout;
}

void checkDataSize(const rosmsg::PointCloud2& cloud, const CloudLayout& layout, const std::string& where) {
  if (cloud.width == 0 || cloud.height == 0) return;
  // Rows that overlap would let a few bytes claim any number of points.
  if (cloud.height > 1 && cloud.row_step < static_cast<std::uint64_t>(cloud.width) * cloud.point_step)
    throw Error(where, fmt::format("PointCloud2 row_step {} is shorter than a row of {} points of point_step {}",
                                   cloud.row_step, cloud.width, cloud.point_step));
  const std::uint64_t needed = static_cast<std::uint64_t>(cloud.height - 1) * cloud.row_step +
                               static_cast<std::uint64_t>(cloud.width - 1) * cloud.point_step + layout.end;
  if (needed > cloud.data.size())
    throw Error(where, fmt::format("PointCloud2 data has {} bytes, its layout ({} x {} points, point_step {}, "
                                   "row_step {}) needs {}", cloud.data.size(), cloud.height, cloud.width,
                                   cloud.point_step, cloud.row_step, needed));
}

// A point's time relative to the header stamp, before deciding whether the
// raw values are absolute: kept as (whole seconds, rest) for split fields so
// that Unix times keep their nanoseconds.
struct RawTime {
  double whole = 0.0, rest = 0.0;
  double value() const { return whole + rest; }
};

RawTime readRawTime(const CloudLayout& layout, const std::uint8_t* point) {
  if (layout.time_sec) return {layout.time_sec->read(point), 1e-9 * layout.time_nsec->read(point)};
  double v = layout.time->read(point);
  // Integer fields (Ouster `t`) and float values too large for seconds are nanoseconds.
  if (!isFloatType(layout.time->datatype) || std::abs(v) > 1e12) v *= 1e-9;
  return {v, 0.0};
}

// Absolute point times lie near the stamp, relative ones near zero.
double relativeTime(const RawTime& raw, bool absolute, const ros::Time& stamp) {
  if (!absolute) return raw.value();
  return (raw.whole - static_cast<double>(stamp.sec)) + (raw.rest - 1e-9 * static_cast<double>(stamp.nsec));
}

void setReference(DecodedScan& out) {
  if (!out.scan.has_time || out.scan.empty()) return;
  float lo = out.scan.points.front().time, hi = lo;
  for (const LidarPoint& p : out.scan.points) {
    lo = std::min(lo, p.time);
    hi = std::max(hi, p.time);
  }
  if (lo >= -kReferenceTolerance) {
    out.time_reference = TimeReference::kStart;
  } else if (hi <= kReferenceTolerance) {
    out.time_reference = TimeReference::kEnd;
  } else {
    out.time_reference = TimeReference::kStart;
    out.restamped = true;
    restampScan(out.scan, TimeReference::kStart);
  }
}

}  // namespace

void restampScan(LidarScan& scan, TimeReference reference) {
  if (scan.empty()) return;
  double shift = scan.points.front().time;
  for (const LidarPoint& p : scan.points)
    shift = reference == TimeReference::kStart ? std::min<double>(shift, p.time) : std::max<double>(shift, p.time);
  scan.timestamp += shift;
  for (LidarPoint& p : scan.points) p.time = static_cast<float>(p.time - shift);
}

DecodedScan decodePointCloud2(const std::vector<std::uint8_t>& serialized, const std::string& where) {
  const auto cloud = rosmsg::deserialize<rosmsg::PointCloud2>(serialized, where);
  const CloudLayout layout = findLayout(cloud, where);
  checkDataSize(cloud, layout, where);

  DecodedScan out;
  out.frame_id = cloud.header.frame_id.c_str();
  out.scan.timestamp = rosmsg::toSeconds(cloud.header.stamp);
  out.scan.has_intensity = layout.intensity.has_value();
  out.scan.has_ring = layout.ring.has_value();
  out.scan.has_time = layout.time || layout.time_sec;
  out.total_points = static_cast<std::size_t>(cloud.width) * cloud.height;
  out.scan.points.reserve(out.total_points);

  std::optional<bool> absolute;  // decided on the first valid point
  for (std::uint32_t r = 0; r < cloud.height; ++r) {
    for (std::uint32_t c = 0; c < cloud.width; ++c) {
      const std::uint8_t* point = cloud.data.data() + static_cast<std::size_t>(r) * cloud.row_step +
                                  static_cast<std::size_t>(c) * cloud.point_step;
      LidarPoint p;
      p.p = Eigen::Vector3d(layout.x.read(point), layout.y.read(point), layout.z.read(point)).cast<float>();
      if (out.scan.has_time) {
        const RawTime raw = readRawTime(layout, point);
        const double stamp = out.scan.timestamp;
        if (!absolute && std::isfinite(raw.value())) absolute = std::abs(raw.value() - stamp) < std::abs(raw.value());
        p.time = static_cast<float>(relativeTime(raw, absolute.value_or(false), cloud.header.stamp));
      }
      if (!p.p.allFinite() || p.p.squaredNorm() == 0.0f || !std::isfinite(p.time)) {
        ++out.invalid_points;
        continue;
      }
      if (layout.intensity) p.intensity = static_cast<float>(layout.intensity->read(point));
      if (layout.ring) {
        const double ring = layout.ring->read(point);
        p.ring = ring >= 0.0 && ring < 65536.0 ? static_cast<std::uint16_t>(ring) : 0;
      }
      out.scan.points.push_back(p);
    }
  }
  setReference(out);
  return out;
}

}  // namespace lvslam
