#include "lvslam/sim/camera_renderer.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include <opencv2/imgproc.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "lvslam/sim/counter_random.h"

namespace lvslam::sim {

namespace {
constexpr int kTileSize = 16;
constexpr double kNearPlane = 0.05;
// Normalised image coordinates (about 12 pixels) a rolling-shutter band's cull
// is widened by: far more than 1 rad/s or 2 m/s at 0.3 m move in 0.4 ms.
constexpr double kRollingCullMargin = 0.02;
}  // namespace

CameraRenderer::CameraRenderer(const Scenario& scenario) : scenario_(scenario) {
  const PinholeCamera& cam = scenario.camera.camera;
  const int w = cam.width(), h = cam.height();
  rays_.resize(static_cast<std::size_t>(w) * h);
  vignette_.create(h, w, CV_32F);
  const double r_max2 = cam.cx() * cam.cx() + cam.cy() * cam.cy();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      rays_[static_cast<std::size_t>(y) * w + x] = cam.unproject(Eigen::Vector2d(x, y)).normalized();
      const double r2 = (x - cam.cx()) * (x - cam.cx()) + (y - cam.cy()) * (y - cam.cy());
      vignette_.at<float>(y, x) = static_cast<float>(1.0 - scenario.camera.vignetting * r2 / r_max2);
    }
  pixel_angle_ = 1.0 / cam.fx();
  for (int y0 = 0; y0 < h; y0 += kTileSize)
    for (int x0 = 0; x0 < w; x0 += kTileSize) {
      Tile tile{x0, y0, std::min(x0 + kTileSize, w), std::min(y0 + kTileSize, h),
                Eigen::Vector2d::Constant(1e300), Eigen::Vector2d::Constant(-1e300)};
      for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
          const Eigen::Vector3d& r = rays_[static_cast<std::size_t>(y) * w + x];
          const Eigen::Vector2d n = r.head<2>() / r.z();
          tile.lo = tile.lo.cwiseMin(n);
          tile.hi = tile.hi.cwiseMax(n);
        }
      tiles_.push_back(tile);
    }
  tile_columns_ = (w + kTileSize - 1) / kTileSize;
  column_x_.assign(tile_columns_, Eigen::Vector2d(1e300, -1e300));
  row_y_.assign(tiles_.size() / tile_columns_, Eigen::Vector2d(1e300, -1e300));
  for (std::size_t k = 0; k < tiles_.size(); ++k) {
    Eigen::Vector2d& x = column_x_[k % tile_columns_];
    Eigen::Vector2d& y = row_y_[k / tile_columns_];
    x = Eigen::Vector2d(std::min(x[0], tiles_[k].lo.x()), std::max(x[1], tiles_[k].hi.x()));
    y = Eigen::Vector2d(std::min(y[0], tiles_[k].lo.y()), std::max(y[1], tiles_[k].hi.y()));
  }
}

// The projection of a convex polytope clipped to z >= near is bounded by its
// front corners and the points where its edges cross the near plane.
void CameraRenderer::cullPerTile(const std::vector<Primitive>& primitives, const Eigen::Isometry3d& T_world_camera,
                                 int y0, int y1, double margin, std::vector<std::vector<int>>& lists) const {
  const Eigen::Isometry3d T_camera_world = T_world_camera.inverse();
  for (std::size_t id = 0; id < primitives.size(); ++id) {
    if (primitives[id].glass) continue;
    const BoundingPolytope poly = boundingPolytope(primitives[id]);
    std::vector<Eigen::Vector3d> c;
    for (const auto& corner : poly.corners) c.push_back(T_camera_world * corner);
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e300), hi = Eigen::Vector2d::Constant(-1e300);
    auto add = [&](const Eigen::Vector3d& p) {
      const Eigen::Vector2d n = p.head<2>() / p.z();
      lo = lo.cwiseMin(n);
      hi = hi.cwiseMax(n);
    };
    for (const auto& p : c)
      if (p.z() >= kNearPlane) add(p);
    for (const auto& e : *poly.edges) {
      const Eigen::Vector3d &a = c[e[0]], &b = c[e[1]];
      if ((a.z() < kNearPlane) != (b.z() < kNearPlane)) add(a + (b - a) * ((kNearPlane - a.z()) / (b.z() - a.z())));
    }
    if (lo.x() > hi.x()) continue;  // entirely behind the camera
    lo.array() -= margin;
    hi.array() += margin;
    for (std::size_t row = 0; row < row_y_.size(); ++row) {
      const int row_y0 = static_cast<int>(row) * kTileSize;
      if (row_y0 < y0 || row_y0 >= y1 || lo.y() > row_y_[row][1] || hi.y() < row_y_[row][0]) continue;
      for (int column = 0; column < tile_columns_; ++column) {
        if (lo.x() > column_x_[column][1] || hi.x() < column_x_[column][0]) continue;
        const std::size_t k = row * tile_columns_ + column;
        const Tile& tile = tiles_[k];
        if (lo.x() <= tile.hi.x() && hi.x() >= tile.lo.x() && lo.y() <= tile.hi.y() && hi.y() >= tile.lo.y())
          lists[k].push_back(static_cast<int>(id));
      }
    }
  }
}

double CameraRenderer::rowTime(double t, int y) const {
  const double line_time = scenario_.camera.line_time;
  if (line_time == 0.0) return t;
  return t + (y - 0.5 * (scenario_.camera.camera.height() - 1)) * line_time;
}

// Lambertian: ambient + main light + lamps falling off with the squared distance.
double CameraRenderer::radianceOf(const Eigen::Vector3d& point, const Eigen::Vector3d& normal, double albedo) const {
  const Lighting& light = scenario_.lighting;
  double irradiance = light.ambient + light.directional * std::max(0.0, normal.dot(light.toward_light));
  for (const PointLight& lamp : light.lamps) {
    const Eigen::Vector3d to_lamp = lamp.position - point;
    const double d2 = std::max(to_lamp.squaredNorm(), 0.25);
    irradiance += lamp.power * std::max(0.0, normal.dot(to_lamp) / std::sqrt(d2)) / d2;
  }
  return albedo * irradiance;
}

// With a rolling shutter the primitives are culled once per band of tile
// rows, at the pose of the band's middle row and with a margin that covers
// the motion within the band (16 rows, under a millisecond).
void CameraRenderer::renderInstant(double t, cv::Mat& radiance, cv::Mat* depth) const {
  const int w = scenario_.camera.camera.width(), h = scenario_.camera.camera.height();
  const bool rolling = scenario_.camera.line_time != 0.0;
  // Per row (one for a global shutter): the camera pose and the people.
  std::vector<Eigen::Isometry3d> T_world_row(rolling ? h : 1);
  std::vector<std::vector<Primitive>> people_row(T_world_row.size());
  for (std::size_t y = 0; y < T_world_row.size(); ++y) {
    T_world_row[y] = scenario_.T_world_camera(rowTime(t, static_cast<int>(y)));
    people_row[y] = peopleAt(scenario_.people, rowTime(t, static_cast<int>(y)));
  }
  const auto& primitives = scenario_.world.primitives();
  std::vector<std::vector<int>> lists(tiles_.size()), people_lists(tiles_.size());
  if (!rolling) {
    cullPerTile(primitives, T_world_row[0], 0, h, 0.0, lists);
    cullPerTile(people_row[0], T_world_row[0], 0, h, 0.0, people_lists);
  }
  for (int y0 = 0; rolling && y0 < h; y0 += kTileSize) {
    const int mid = std::min(y0 + kTileSize / 2, h - 1);
    cullPerTile(primitives, T_world_row[mid], y0, y0 + kTileSize, kRollingCullMargin, lists);
    cullPerTile(people_row[mid], T_world_row[mid], y0, y0 + kTileSize, kRollingCullMargin, people_lists);
  }
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, tiles_.size()), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t k = r.begin(); k != r.end(); ++k) {
      const Tile& tile = tiles_[k];
      for (int y = tile.y0; y < tile.y1; ++y) {
        const Eigen::Isometry3d& T_world_camera = T_world_row[rolling ? y : 0];
        const Eigen::Matrix3d R = T_world_camera.linear();
        const Eigen::Vector3d origin = T_world_camera.translation();
        const std::vector<Primitive>& people = people_row[rolling ? y : 0];
        for (int x = tile.x0; x < tile.x1; ++x) {
          const Eigen::Vector3d& ray = rays_[static_cast<std::size_t>(y) * w + x];
          const Eigen::Vector3d dir = R * ray;
          auto hit = scenario_.world.raycastAmong(lists[k], origin, dir, 1e9, pixel_angle_);
          for (const int i : people_lists[k])
            addPersonHit(scenario_.world, people[i], origin, dir, 1e9, pixel_angle_, hit);
          float value = 0.0f, z = 0.0f;
          if (hit) {
            value = static_cast<float>(radianceOf(origin + hit->distance * dir, hit->normal, hit->albedo));
            z = static_cast<float>(hit->distance * ray.z());
          } else {  // open sky, a little darker towards the horizon
            value = static_cast<float>(scenario_.lighting.sky * (0.85 + 0.15 * std::max(0.0, dir.z())));
          }
          radiance.at<float>(y, x) += value;
          if (depth) depth->at<float>(y, x) = z;
        }
      }
    }
  });
}

cv::Mat CameraRenderer::renderDepth(double t) const {
  const PinholeCamera& cam = scenario_.camera.camera;
  cv::Mat radiance = cv::Mat::zeros(cam.height(), cam.width(), CV_32F);
  cv::Mat depth = cv::Mat::zeros(cam.height(), cam.width(), CV_32F);
  renderInstant(t, radiance, &depth);
  return depth;
}

cv::Mat CameraRenderer::renderImage(double t) const {
  return renderImage(t, Exposure{scenario_.camera.exposure, 1.0});
}

cv::Mat CameraRenderer::renderImage(double t, const Exposure& exposure) const {
  const CameraConfig& config = scenario_.camera;
  const PinholeCamera& cam = config.camera;
  cv::Mat radiance = cv::Mat::zeros(cam.height(), cam.width(), CV_32F);
  const int n = std::max(config.blur_samples, 1);
  for (int k = 0; k < n; ++k) {  // the shutter stays open while the robot moves
    const double tk = n == 1 ? t : t + exposure.time * (static_cast<double>(k) / (n - 1) - 0.5);
    renderInstant(tk, radiance, nullptr);
  }
  radiance *= config.gain * exposure.factor(config.exposure) / n;
  // Analog gain amplifies the read noise and each photon's share of the signal.
  const double read_noise = config.read_noise * exposure.gain;
  const double shot_variance = config.shot_noise * config.shot_noise * exposure.gain;
  cv::multiply(radiance, vignette_, radiance);
  cv::GaussianBlur(radiance, radiance, cv::Size(3, 3), 0.6);  // lens and demosaicing softness
  const CounterRandom noise(scenario_.options.seed, RandomStream::kCamera, std::bit_cast<std::uint64_t>(t));
  cv::Mat image(cam.height(), cam.width(), CV_8U);
  tbb::parallel_for(0, cam.height(), [&](int y) {
    for (int x = 0; x < cam.width(); x += 2) {  // one Box-Muller pair per two pixels
      const auto pair = noise.normalPairAt((static_cast<std::uint64_t>(y) * cam.width() + x) / 2);
      for (int i = 0; i < 2 && x + i < cam.width(); ++i) {
        const double dn = radiance.at<float>(y, x + i);
        const double sigma = std::sqrt(read_noise * read_noise + shot_variance * std::max(dn, 0.0));
        const double value = dn + sigma * (i == 0 ? pair.x : pair.y);
        image.at<std::uint8_t>(y, x + i) = static_cast<std::uint8_t>(std::clamp(std::lround(value), 0L, 255L));
      }
    }
  });
  return image;
}

}  // namespace lvslam::sim
