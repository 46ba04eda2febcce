#include "lvslam/io/ply_reader.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam {

namespace {

struct PlyHeader {
  std::string format;
  // Elements in file order: name, count, property names.
  struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<std::string> properties, types;
  };
  std::vector<Element> elements;

  const Element* element(const std::string& name) const {
    for (const Element& e : elements)
      if (e.name == name) return &e;
    return nullptr;
  }
};

PlyHeader readHeader(std::istream& in, const std::string& path) {
  std::string line;
  if (!std::getline(in, line) || line != "ply") throw Error(path, "not a PLY file (no 'ply' first line)");
  PlyHeader header;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "end_header") return header;
    if (key == "format") {
      words >> header.format;
    } else if (key == "element") {
      PlyHeader::Element e;
      if (!(words >> e.name >> e.count)) throw Error(path, "bad PLY element line: " + line);
      header.elements.push_back(e);
    } else if (key == "property") {
      std::string type, name;
      if (!(words >> type >> name) || header.elements.empty()) throw Error(path, "bad PLY property line: " + line);
      header.elements.back().types.push_back(type);
      header.elements.back().properties.push_back(name);
    }
  }
  throw Error(path, "PLY header has no end_header (truncated?)");
}

// Bytes between the stream's position and the end of the file.
std::size_t bytesLeft(std::istream& in) {
  const std::streampos here = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streampos end = in.tellg();
  in.seekg(here);
  return here >= 0 && end >= here ? static_cast<std::size_t>(end - here) : 0;
}

// A count the rest of the file cannot hold, at `min_bytes` per item, is a
// damaged header: an error before anything that large is allocated.
void checkCount(const std::string& path, const PlyHeader::Element& e, std::size_t min_bytes, std::size_t bytes_left) {
  if (e.count > bytes_left / min_bytes)
    throw Error(path, fmt::format("truncated: the header announces {} {} elements, the {} bytes after it hold at most {}",
                                  e.count, e.name, bytes_left, bytes_left / min_bytes));
}

}  // namespace

std::vector<PlyPoint> readPointCloudPly(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot read the file");
  const PlyHeader header = readHeader(in, path);
  const PlyHeader::Element* vertex = header.element("vertex");
  const std::vector<std::string> expected = {"x", "y", "z", "intensity"};
  if (header.format != "binary_little_endian" || !vertex || vertex->properties != expected ||
      std::any_of(vertex->types.begin(), vertex->types.end(), [](const std::string& t) { return t != "float"; }))
    throw Error(path, "expected a binary little-endian PLY of float x, y, z, intensity (as lvslam writes map.ply)");
  checkCount(path, *vertex, 4 * sizeof(float), bytesLeft(in));
  std::vector<float> values(4 * vertex->count);
  in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(values.size() * sizeof(float)));
  if (static_cast<std::size_t>(in.gcount()) != values.size() * sizeof(float))
    throw Error(path, fmt::format("truncated: the header announces {} vertices", vertex->count));
  std::vector<PlyPoint> points(vertex->count);
  for (std::size_t i = 0; i < points.size(); ++i) {
    points[i].p = Eigen::Vector3f(values[4 * i], values[4 * i + 1], values[4 * i + 2]);
    points[i].intensity = values[4 * i + 3];
  }
  return points;
}

std::vector<PlySegment> readLineSegmentsPly(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot read the file");
  const PlyHeader header = readHeader(in, path);
  const PlyHeader::Element* vertex = header.element("vertex");
  const PlyHeader::Element* edge = header.element("edge");
  if (header.format != "ascii" || !vertex || !edge || vertex->properties.size() != 3 || edge->properties.size() != 5)
    throw Error(path, "expected an ASCII PLY of vertices and coloured edges (as lvslam writes lines.ply)");
  // ASCII: at least a digit and a separator per number.
  const std::size_t bytes_left = bytesLeft(in);
  checkCount(path, *vertex, 2 * 3, bytes_left);
  checkCount(path, *edge, 2 * 5, bytes_left);
  std::vector<Eigen::Vector3d> vertices(vertex->count);
  for (Eigen::Vector3d& v : vertices)
    if (!(in >> v.x() >> v.y() >> v.z())) throw Error(path, "truncated or malformed vertex list");
  std::vector<PlySegment> segments(edge->count);
  for (PlySegment& s : segments) {
    std::size_t a = 0, b = 0;
    int r = 0, g = 0, bl = 0;
    if (!(in >> a >> b >> r >> g >> bl)) throw Error(path, "truncated or malformed edge list");
    if (a >= vertices.size() || b >= vertices.size()) throw Error(path, fmt::format("edge vertex {} or {} out of range", a, b));
    s.a = vertices[a];
    s.b = vertices[b];
    s.r = static_cast<unsigned char>(r);
    s.g = static_cast<unsigned char>(g);
    s.b_colour = static_cast<unsigned char>(bl);
  }
  return segments;
}

}  // namespace lvslam
