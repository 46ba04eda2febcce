// A KITTI raw drive of a few frames made here, with the calibration files of
// the real 2011_09_26 drives, converted to a sequence folder.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "lvslam/core/se3.h"
#include "lvslam/io/kitti_raw_calib.h"
#include "lvslam/io/kitti_raw_convert.h"
#include "lvslam/io/kitti_raw_oxts.h"
#include "lvslam/io/kitti_raw_time.h"
#include "lvslam/io/sequence_reader.h"
#include "support/temp_dir.h"

namespace lvslam {
namespace {

// 2011_09_26/calib_cam_to_cam.txt (cameras 0 and 2), calib_velo_to_cam.txt, calib_imu_to_velo.txt.
constexpr const char* kCamToCam = R"(calib_time: 09-Jan-2012 13:57:47
corner_dist: 9.950000e-02
S_00: 1.392000e+03 5.120000e+02
K_00: 9.842439e+02 0.000000e+00 6.900000e+02 0.000000e+00 9.808141e+02 2.331966e+02 0.000000e+00 0.000000e+00 1.000000e+00
D_00: -3.728755e-01 2.037299e-01 2.219027e-03 1.383707e-03 -7.233722e-02
R_00: 1.000000e+00 0.000000e+00 0.000000e+00 0.000000e+00 1.000000e+00 0.000000e+00 0.000000e+00 0.000000e+00 1.000000e+00
T_00: 2.573699e-16 -1.059758e-16 1.614870e-16
S_rect_00: 1.242000e+03 3.750000e+02
R_rect_00: 9.999239e-01 9.837760e-03 -7.445048e-03 -9.869795e-03 9.999421e-01 -4.278459e-03 7.402527e-03 4.351614e-03 9.999631e-01
P_rect_00: 7.215377e+02 0.000000e+00 6.095593e+02 0.000000e+00 0.000000e+00 7.215377e+02 1.728540e+02 0.000000e+00 0.000000e+00 0.000000e+00 1.000000e+00 0.000000e+00
S_02: 1.392000e+03 5.120000e+02
K_02: 9.597910e+02 0.000000e+00 6.960217e+02 0.000000e+00 9.569251e+02 2.241806e+02 0.000000e+00 0.000000e+00 1.000000e+00
D_02: -3.691481e-01 1.968681e-01 1.353473e-03 5.677587e-04 -6.770705e-02
R_02: 9.999758e-01 -5.267463e-03 -4.552439e-03 5.251945e-03 9.999804e-01 -3.413835e-03 4.570332e-03 3.389843e-03 9.999838e-01
T_02: 5.956621e-02 2.900141e-04 2.577209e-03
S_rect_02: 1.242000e+03 3.750000e+02
R_rect_02: 9.998817e-01 1.511453e-02 -2.841595e-03 -1.511724e-02 9.998853e-01 -9.338510e-04 2.827154e-03 9.766976e-04 9.999955e-01
P_rect_02: 7.215377e+02 0.000000e+00 6.095593e+02 4.485728e+01 0.000000e+00 7.215377e+02 1.728540e+02 2.163791e-01 0.000000e+00 0.000000e+00 1.000000e+00 2.745884e-03
)";
constexpr const char* kVeloToCam = R"(calib_time: 15-Mar-2012 11:37:16
R: 7.533745e-03 -9.999714e-01 -6.166020e-04 1.480249e-02 7.280733e-04 -9.998902e-01 9.998621e-01 7.523790e-03 1.480755e-02
T: -4.069766e-03 -7.631618e-02 -2.717806e-01
delta_f: 0.000000e+00 0.000000e+00
delta_c: 0.000000e+00 0.000000e+00
)";
constexpr const char* kImuToVelo = R"(calib_time: 25-May-2012 16:47:16
R: 9.999976e-01 7.553071e-04 -2.035826e-03 -7.854027e-04 9.998898e-01 -1.482298e-02 2.024406e-03 1.482454e-02 9.998881e-01
T: -8.086759e-01 3.195559e-01 -7.997231e-01
)";

// The same numbers as matrices, for KITTI's own projection P_rect * R_rect_00 * Tr_velo_to_cam.
Eigen::Matrix4d homogeneous(const std::vector<double>& r9, const std::vector<double>& t3) {
  Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
  for (int i = 0; i < 9; ++i) M(i / 3, i % 3) = r9[i];
  for (int i = 0; i < 3; ++i) M(i, 3) = t3.empty() ? 0.0 : t3[i];
  return M;
}

const Eigen::Matrix4d kRrect00 = homogeneous({9.999239e-01, 9.837760e-03, -7.445048e-03, -9.869795e-03, 9.999421e-01,
                                              -4.278459e-03, 7.402527e-03, 4.351614e-03, 9.999631e-01}, {});
const Eigen::Matrix4d kTrVeloToCam = homogeneous({7.533745e-03, -9.999714e-01, -6.166020e-04, 1.480249e-02, 7.280733e-04,
                                                  -9.998902e-01, 9.998621e-01, 7.523790e-03, 1.480755e-02},
                                                 {-4.069766e-03, -7.631618e-02, -2.717806e-01});
Eigen::Matrix<double, 3, 4> kittiP(int camera) {
  Eigen::Matrix<double, 3, 4> P;
  if (camera == 0)
    P << 7.215377e+02, 0, 6.095593e+02, 0, 0, 7.215377e+02, 1.728540e+02, 0, 0, 0, 1, 0;
  else
    P << 7.215377e+02, 0, 6.095593e+02, 4.485728e+01, 0, 7.215377e+02, 1.728540e+02, 2.163791e-01, 0, 0, 1, 2.745884e-03;
  return P;
}

const std::vector<Eigen::Vector3d> kVeloPoints{{10.0, 1.0, -1.2}, {25.0, -4.0, 0.5}, {6.0, 2.5, -1.6}, {40.0, 8.0, 2.0}};

Eigen::Vector2d kittiProjection(int camera, const Eigen::Vector3d& p) {
  const Eigen::Vector3d x = kittiP(camera) * kRrect00 * kTrVeloToCam * p.homogeneous();
  return x.hnormalized();
}

Eigen::Vector2d ourProjection(const PinholeCamera& camera, const Eigen::Isometry3d& T_camera_lidar, const Eigen::Vector3d& p) {
  return *camera.projectUndistorted(T_camera_lidar * p);
}

const std::vector<std::string> kTimes{"2011-09-26 13:02:25.964389445", "2011-09-26 13:02:26.068308278",
                                      "2011-09-26 13:02:26.172227111"};

void writeTimes(const testing::TempDir& dir, const std::string& name, double shift) {
  std::string text;
  for (const std::string& t : kTimes)  // "YYYY-MM-DD hh:mm:" + seconds shifted (no minute carry here)
    text += fmt::format("{}{:012.9f}\n", t.substr(0, 17), std::stod(t.substr(17)) + shift);
  dir.write(name, text);
}

// A drive of 3 frames: image_00, image_02, velodyne_points, oxts.
void writeDrive(const testing::TempDir& dir) {
  dir.write("calib/calib_cam_to_cam.txt", kCamToCam);
  dir.write("calib/calib_velo_to_cam.txt", kVeloToCam);
  dir.write("calib/calib_imu_to_velo.txt", kImuToVelo);
  const std::string drive = "2011_09_26_drive_0001_sync/";
  for (const std::string cam : {"image_00", "image_02"}) {
    writeTimes(dir, drive + cam + "/timestamps.txt", 0.0);
    std::filesystem::create_directories(dir.path() / drive / cam / "data");
    for (int i = 0; i < 3; ++i) {
      cv::Mat image(375, 1242, cam == "image_00" ? CV_8UC1 : CV_8UC3, cv::Scalar::all(20 * i + 7));
      cv::imwrite(dir.file(drive + cam + fmt::format("/data/{:010d}.png", i)), image);
    }
  }
  writeTimes(dir, drive + "velodyne_points/timestamps.txt", 0.0);
  writeTimes(dir, drive + "velodyne_points/timestamps_start.txt", -0.05);
  writeTimes(dir, drive + "velodyne_points/timestamps_end.txt", 0.05);
  std::filesystem::create_directories(dir.path() / drive / "velodyne_points/data");
  for (int i = 0; i < 3; ++i) {
    std::vector<float> records;
    for (const Eigen::Vector3d& p : kVeloPoints)
      for (const double v : {p.x() + i, p.y(), p.z(), 0.25 * i}) records.push_back(static_cast<float>(v));
    std::ofstream(dir.file(drive + fmt::format("velodyne_points/data/{:010d}.bin", i)), std::ios::binary)
        .write(reinterpret_cast<const char*>(records.data()), static_cast<std::streamsize>(records.size() * 4));
  }
  writeTimes(dir, drive + "oxts/timestamps.txt", 0.0);
  // The first packet of 2011_09_26_drive_0001, then due east by 0.0001 degree of longitude a step.
  for (int i = 0; i < 3; ++i)
    dir.write(drive + fmt::format("oxts/data/{:010d}.txt", i),
              fmt::format("49.015003823272 {:.12f} 116.43032836914 0.035752 0.00903 -0.0 "
                          "0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0 0.1 0.1 4 11 6 6 6\n",
                          8.4342971002 + 1e-4 * i));
}

TEST(KittiRawTime, ParsesKittiTimestampsToUnixSeconds) {
  // 2011-09-26 13:02:25 UTC is 1317042145 s after the epoch (Python calendar.timegm).
  const auto t = parseKittiTimestamp("2011-09-26 13:02:25.964389445");
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 1317042145.964389445, 1e-6);
  EXPECT_FALSE(parseKittiTimestamp("2011-09-26T13:02:25").has_value());
  EXPECT_FALSE(parseKittiTimestamp("2011-13-26 13:02:25.1").has_value());
  EXPECT_FALSE(parseKittiTimestamp("2011-09-26 13:02:25.1 junk").has_value());
}

TEST(KittiRawCalib, TheCalibrationChainProjectsAsKittiDoes) {
  testing::TempDir dir;
  writeDrive(dir);
  for (const int camera : {0, 2}) {
    const KittiRawCalibration calib = readKittiRawCalibration(dir.file("calib"), camera);
    EXPECT_EQ(calib.camera.width(), 1242);
    EXPECT_EQ(calib.camera.height(), 375);
    for (const Eigen::Vector3d& p : kVeloPoints) {
      const Eigen::Vector2d expected = kittiProjection(camera, p);
      const Eigen::Vector2d ours = ourProjection(calib.camera, calib.T_camera_lidar, p);
      EXPECT_NEAR((ours - expected).norm(), 0.0, 1e-6) << "camera " << camera << " point " << p.transpose();
    }
  }
  // Camera 2 sits about 6 cm beside camera 0: the offset t with K t = P_rect_02's 4th column.
  const auto c0 = readKittiRawCalibration(dir.file("calib"), 0), c2 = readKittiRawCalibration(dir.file("calib"), 2);
  const Eigen::Vector3d offset((4.485728e+01 - 6.095593e+02 * 2.745884e-03) / 7.215377e+02,
                               (2.163791e-01 - 1.728540e+02 * 2.745884e-03) / 7.215377e+02, 2.745884e-03);
  EXPECT_NEAR((c2.T_camera_lidar.translation() - c0.T_camera_lidar.translation() - offset).norm(), 0.0, 1e-12);
  const std::string message = testing::errorMessageOf([&] { readKittiRawCalibration(dir.file("nowhere"), 0); });
  EXPECT_NE(message.find("calib_cam_to_cam.txt"), std::string::npos) << message;
}

TEST(KittiRawConvert, ConvertsADriveWithCalibrationScansAndGroundTruth) {
  testing::TempDir dir;
  writeDrive(dir);
  for (const int camera : {0, 2}) {
    KittiRawConvertOptions options;
    options.drive_dir = dir.file("2011_09_26_drive_0001_sync");
    options.calib_dir = dir.file("calib");
    options.camera = camera;
    options.out_dir = dir.file(fmt::format("seq{}", camera));
    const KittiRawConvertStats stats = convertKittiRaw(options);
    EXPECT_EQ(stats.images, 3u);
    EXPECT_EQ(stats.scans, 3u);
    EXPECT_EQ(stats.groundtruth, 3u);

    SequenceReader reader(options.out_dir);
    EXPECT_EQ(reader.info().name, "2011_09_26_drive_0001_sync");
    const PinholeCamera& cam = reader.info().camera->camera;
    EXPECT_EQ(cam.fx(), 7.215377e+02);
    EXPECT_EQ(cam.cy(), 1.728540e+02);
    // The folder holds the chain, its rotation snapped to the closest one (sequence-format rule).
    const KittiRawCalibration calib = readKittiRawCalibration(options.calib_dir, camera);
    EXPECT_TRUE(reader.info().T_camera_lidar.linear().isApprox(closestRotation(calib.T_camera_lidar.linear()), 1e-12));
    EXPECT_TRUE(reader.info().T_camera_lidar.translation().isApprox(calib.T_camera_lidar.translation(), 1e-12));
    for (const Eigen::Vector3d& p : kVeloPoints)
      EXPECT_LT((ourProjection(cam, reader.info().T_camera_lidar, p) - kittiProjection(camera, p)).norm(), 0.01);

    // Images as written, scans at the sweep start with their points.
    EXPECT_EQ(reader.loadImage(1).image.channels(), camera == 0 ? 1 : 3);
    EXPECT_EQ(reader.loadImage(1).image.at<uchar>(10, 10), 27);
    EXPECT_NEAR(reader.loadImage(2).timestamp, *parseKittiTimestamp(kTimes[2]), 1e-6);
    const LidarScan scan = reader.loadScan(2);
    EXPECT_NEAR(scan.timestamp, *parseKittiTimestamp(kTimes[2]) - 0.05, 1e-6);
    ASSERT_EQ(scan.size(), kVeloPoints.size());
    EXPECT_EQ(scan.points[1].p, (kVeloPoints[1] + Eigen::Vector3d(2, 0, 0)).cast<float>());
    EXPECT_EQ(scan.points[1].intensity, 0.5f);
  }
}

TEST(KittiRawOxts, GroundTruthFollowsTheDevkitProjectionInTheLidarFrame) {
  testing::TempDir dir;
  writeDrive(dir);
  KittiRawConvertOptions options;
  options.drive_dir = dir.file("2011_09_26_drive_0001_sync");
  options.calib_dir = dir.file("calib");
  options.out_dir = dir.file("seq");
  convertKittiRaw(options);
  SequenceReader reader(options.out_dir);
  ASSERT_EQ(reader.info().groundtruth_frame, GroundTruthFrame::kLidar);
  const Trajectory gt = reader.groundTruth();
  ASSERT_EQ(gt.size(), 3u);
  // Same latitude, longitude + 1e-4 degree: the Mercator x grows by
  // cos(lat0) * 1e-4 deg * pi / 180 * 6378137 m; the attitude is fixed.
  const double step = std::cos(49.015003823272 * std::numbers::pi / 180) * 1e-4 * std::numbers::pi / 180 * 6378137.0;
  const KittiRawCalibration calib = readKittiRawCalibration(options.calib_dir, 0);
  const Eigen::Isometry3d T_imu_velo = calib.T_velo_imu.inverse();
  for (std::size_t i = 0; i < 3; ++i) {
    // T_world_lidar(i) = T_world_imu(i) * T_imu_velo, T_world_imu(0) = I.
    const Eigen::Isometry3d T_world_imu = gt[i].T_world_frame * T_imu_velo.inverse();
    const Eigen::Matrix3d R0 = (Eigen::AngleAxisd(-0.0, Eigen::Vector3d::UnitZ()) *
                                Eigen::AngleAxisd(0.00903, Eigen::Vector3d::UnitY()) *
                                Eigen::AngleAxisd(0.035752, Eigen::Vector3d::UnitX())).toRotationMatrix();
    // world = first IMU pose: the east step expressed in the first IMU frame.
    const Eigen::Vector3d expected = R0.transpose() * Eigen::Vector3d(step * i, 0, 0);
    EXPECT_NEAR((T_world_imu.translation() - expected).norm(), 0.0, 2e-6) << i;
    EXPECT_NEAR(rotationAngle(T_world_imu), 0.0, 1e-6);
    EXPECT_NEAR(gt[i].t, *parseKittiTimestamp(kTimes[i]), 1e-6);
  }
}

}  // namespace
}  // namespace lvslam
