#include "lvslam/io/ply_writer.h"

#include <fstream>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam {

namespace {

std::ofstream openPly(const std::string& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw Error(path, "cannot write file");
  return out;
}

template <typename T>
void put(std::ofstream& out, T value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

}  // namespace

void writePointCloudPly(const std::string& path, const std::vector<PlyPoint>& points) {
  std::ofstream out = openPly(path);
  out << "ply\nformat binary_little_endian 1.0\ncomment lvslam LiDAR map\n"
      << fmt::format("element vertex {}\n", points.size())
      << "property float x\nproperty float y\nproperty float z\nproperty float intensity\nend_header\n";
  for (const PlyPoint& q : points) {
    put(out, q.p.x());
    put(out, q.p.y());
    put(out, q.p.z());
    put(out, q.intensity);
  }
  if (!out) throw Error(path, "write failed");
}

void writeLineSegmentsPly(const std::string& path, const std::vector<PlySegment>& segments) {
  std::ofstream out = openPly(path);
  out << "ply\nformat ascii 1.0\ncomment lvslam 3D line map: one edge per line landmark\n"
      << fmt::format("element vertex {}\n", 2 * segments.size())
      << "property double x\nproperty double y\nproperty double z\n"
      << fmt::format("element edge {}\n", segments.size())
      << "property int vertex1\nproperty int vertex2\n"
      << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
  for (const PlySegment& s : segments)
    out << fmt::format("{:.6f} {:.6f} {:.6f}\n{:.6f} {:.6f} {:.6f}\n", s.a.x(), s.a.y(), s.a.z(), s.b.x(), s.b.y(),
                       s.b.z());
  for (std::size_t i = 0; i < segments.size(); ++i)
    out << fmt::format("{} {} {} {} {}\n", 2 * i, 2 * i + 1, segments[i].r, segments[i].g, segments[i].b_colour);
  if (!out) throw Error(path, "write failed");
}

}  // namespace lvslam
