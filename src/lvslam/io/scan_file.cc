#include "lvslam/io/scan_file.h"

#include <bit>
#include <cmath>
#include <cstring>
#include <fstream>

#include <fmt/format.h>

#include "lvslam/core/error.h"
#include "lvslam/core/file_access.h"

namespace lvslam {

static_assert(std::endian::native == std::endian::little,
              "scan files are little-endian float32; add byte swapping for this platform");

ScanLayout ScanLayout::fromFields(const std::vector<std::string>& point_fields) {
  ScanLayout layout;
  layout.fields = static_cast<int>(point_fields.size());
  for (int i = 0; i < layout.fields; ++i) {
    const std::string& f = point_fields[i];
    if (f == "x") layout.x = i;
    else if (f == "y") layout.y = i;
    else if (f == "z") layout.z = i;
    else if (f == "intensity") layout.intensity = i;
    else if (f == "time") layout.time = i;
    else if (f == "ring") layout.ring = i;
  }
  if (layout.x < 0 || layout.y < 0 || layout.z < 0)
    throw Error("point_fields", "must contain x, y and z");
  return layout;
}

ScanReadStats readScanFile(const std::string& path, const ScanLayout& layout, LidarScan& scan) {
  std::ifstream in = openInputFile(path, "", std::ios::binary | std::ios::ate);
  const auto bytes = static_cast<std::size_t>(in.tellg());
  const std::size_t record = layout.recordBytes();
  if (bytes % record != 0)
    throw Error(path, fmt::format("size {} bytes is not a multiple of the record size {} ({} float32 fields)",
                                  bytes, record, layout.fields));
  std::vector<float> data(bytes / sizeof(float));
  in.seekg(0);
  if (!in.read(reinterpret_cast<char*>(data.data()), static_cast<std::streamsize>(bytes)))
    throw Error(path, "read failed");

  ScanReadStats stats;
  stats.records = bytes / record;
  scan.has_intensity = layout.intensity >= 0;
  scan.has_time = layout.time >= 0;
  scan.has_ring = layout.ring >= 0;
  scan.points.clear();
  scan.points.reserve(stats.records);
  for (std::size_t r = 0; r < stats.records; ++r) {
    const float* rec = data.data() + r * layout.fields;
    LidarPoint p;
    p.p = {rec[layout.x], rec[layout.y], rec[layout.z]};
    p.time = layout.time >= 0 ? rec[layout.time] : 0.0f;
    // Invalid returns: non-finite coordinates, the origin, or no usable time.
    if (!p.p.allFinite() || p.p.squaredNorm() == 0.0f || !std::isfinite(p.time)) {
      ++stats.dropped;
      continue;
    }
    if (layout.intensity >= 0 && std::isfinite(rec[layout.intensity])) p.intensity = rec[layout.intensity];
    if (layout.ring >= 0) {
      const float ring = rec[layout.ring];
      p.ring = (std::isfinite(ring) && ring >= 0.0f && ring < 65536.0f) ? static_cast<std::uint16_t>(ring) : 0;
    }
    scan.points.push_back(p);
  }
  return stats;
}

void writeScanFile(const std::string& path, const std::vector<std::string>& point_fields,
                   const LidarScan& scan) {
  // Field names resolved once, not per point.
  enum class Field { kX, kY, kZ, kIntensity, kTime, kRing, kOther };
  std::vector<Field> order;
  for (const std::string& f : point_fields)
    order.push_back(f == "x" ? Field::kX : f == "y" ? Field::kY : f == "z" ? Field::kZ
                    : f == "intensity" ? Field::kIntensity : f == "time" ? Field::kTime
                    : f == "ring" ? Field::kRing : Field::kOther);
  std::vector<float> data;
  data.reserve(scan.size() * order.size());
  for (const LidarPoint& p : scan.points) {
    for (const Field f : order) {
      switch (f) {
        case Field::kX: data.push_back(p.p.x()); break;
        case Field::kY: data.push_back(p.p.y()); break;
        case Field::kZ: data.push_back(p.p.z()); break;
        case Field::kIntensity: data.push_back(p.intensity); break;
        case Field::kTime: data.push_back(p.time); break;
        case Field::kRing: data.push_back(static_cast<float>(p.ring)); break;
        case Field::kOther: data.push_back(0.0f); break;
      }
    }
  }
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(path, "cannot write scan file");
  out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size() * sizeof(float)));
  if (!out) throw Error(path, "write failed");
}

}  // namespace lvslam
