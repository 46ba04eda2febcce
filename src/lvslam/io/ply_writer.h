#pragma once
// PLY export of maps so users can open them (CloudCompare, MeshLab, Open3D):
// point clouds as binary little-endian vertices with intensity, 3D line maps
// as vertices joined by edges.
#include <string>
#include <vector>

#include <Eigen/Core>

namespace lvslam {

struct PlyPoint {
  Eigen::Vector3f p = Eigen::Vector3f::Zero();
  float intensity = 0.0f;
};

struct PlySegment {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  unsigned char r = 255, g = 0, b_colour = 255;
};

// Throws lvslam::Error naming the file when it cannot be written.
void writePointCloudPly(const std::string& path, const std::vector<PlyPoint>& points);
void writeLineSegmentsPly(const std::string& path, const std::vector<PlySegment>& segments);

}  // namespace lvslam
