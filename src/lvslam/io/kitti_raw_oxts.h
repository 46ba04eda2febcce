#pragma once
// KITTI raw OXTS (GPS/IMU) packets to poses, as the KITTI raw devkit's
// convertOxtsToPose: Mercator projection with the scale of the first
// latitude, rotation Rz(yaw) Ry(pitch) Rx(roll), world = the first IMU pose.
#include <string>
#include <vector>

#include "lvslam/core/trajectory.h"

namespace lvslam {

struct OxtsPacket {
  double lat = 0.0, lon = 0.0, alt = 0.0;     // degrees, degrees, metres
  double roll = 0.0, pitch = 0.0, yaw = 0.0;  // radians
};

// T_world_imu per packet (the first is the identity).
std::vector<Eigen::Isometry3d> oxtsToPoses(const std::vector<OxtsPacket>& packets);

// oxts/timestamps.txt and oxts/data/<index>.txt of a drive: T_world_imu at
// each time stamp. Throws lvslam::Error naming the file on anything missing.
Trajectory readOxtsTrajectory(const std::string& oxts_dir);

}  // namespace lvslam
