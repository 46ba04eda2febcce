#include "lvslam/visual/data/visual_map.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <utility>

#include "lvslam/core/error.h"
#include "lvslam/core/se3.h"
#include "lvslam/visual/match/descriptor_distance.h"

namespace lvslam::visual {

namespace {
// Works for const and non-const maps alike.
template <typename Map>
auto& find(Map& items, int id, const char* what) {
  const auto it = items.find(id);
  if (it == items.end()) throw Error("VisualMap", std::string("unknown ") + what + " id " + std::to_string(id));
  return it->second;
}

template <typename Landmark>
bool alive(const std::vector<Landmark*>& by_id, int id) {
  return id >= 0 && static_cast<size_t>(id) < by_id.size() && by_id[static_cast<size_t>(id)] != nullptr;
}

template <typename Landmark>
Landmark& findById(const std::vector<Landmark*>& by_id, int id, const char* what) {
  if (!alive(by_id, id)) {
    throw Error("VisualMap", std::string("unknown ") + what + " id " + std::to_string(id));
  }
  return *by_id[static_cast<size_t>(id)];
}

// Drops the landmark; its id keeps its slot, null, so it is never reused.
template <typename Landmark>
void erase(std::map<int, Landmark>& landmarks, std::vector<Landmark*>& by_id, int id) {
  landmarks.erase(id);
  by_id[static_cast<size_t>(id)] = nullptr;
}

// Pointers to every landmark by id, into the map's nodes; `count` ids in
// all (removed ones null).
template <typename Landmark>
std::vector<Landmark*> indexById(std::map<int, Landmark>& landmarks, size_t count) {
  std::vector<Landmark*> by_id(count, nullptr);
  for (auto& [id, landmark] : landmarks) by_id[static_cast<size_t>(id)] = &landmark;
  return by_id;
}

// The upper median (the element at size / 2 in order); none when empty.
std::optional<double> upperMedian(std::vector<double> values) {
  if (values.empty()) return std::nullopt;
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

}  // namespace

VisualMap::VisualMap(const VisualMap& other)
    : keyframes_(other.keyframes_), points_(other.points_), lines_(other.lines_),
      covisibility_(other.covisibility_), removed_(other.removed_), next_keyframe_id_(other.next_keyframe_id_),
      T_world_odom_(other.T_world_odom_), point_by_id_(indexById(points_, other.point_by_id_.size())),
      line_by_id_(indexById(lines_, other.line_by_id_.size())) {}

VisualMap& VisualMap::operator=(const VisualMap& other) {
  if (this != &other) *this = VisualMap(other);
  return *this;
}

int VisualMap::addKeyframe(Keyframe keyframe) {
  keyframe.id = next_keyframe_id_++;
  keyframe.point_landmark.assign(keyframe.features.keypoints.size(), -1);
  keyframe.line_landmark.assign(keyframe.features.lines.size(), -1);
  const int id = keyframe.id;
  keyframes_.emplace(id, std::move(keyframe));
  return id;
}

int VisualMap::addPointLandmark(const Eigen::Vector3d& p_world, const cv::Mat& descriptor) {
  if (!p_world.allFinite()) throw Error("VisualMap", "point landmark is not finite");
  PointLandmark p;
  p.id = static_cast<int>(point_by_id_.size());
  p.p_world = p_world;
  p.descriptor = descriptor.clone();
  point_by_id_.push_back(&points_.emplace(p.id, std::move(p)).first->second);
  return point_by_id_.back()->id;
}

int VisualMap::addLineLandmark(const PluckerLine& line_world, const Eigen::Vector3d& start_world,
                               const Eigen::Vector3d& end_world, const cv::Mat& descriptor) {
  if (!line_world.isValid(1e-6)) throw Error("VisualMap", "line landmark is not a valid Plücker line");
  LineLandmark l;
  l.id = static_cast<int>(line_by_id_.size());
  l.line_world = line_world;
  l.start_world = start_world;
  l.end_world = end_world;
  l.descriptor = descriptor.clone();
  line_by_id_.push_back(&lines_.emplace(l.id, std::move(l)).first->second);
  return line_by_id_.back()->id;
}

template <typename Landmark>
void VisualMap::addObservation(Landmark& landmark, std::vector<int> Keyframe::*table, int keyframe, int index) {
  Keyframe& kf = find(keyframes_, keyframe, "keyframe");
  std::vector<int>& slots = kf.*table;
  if (index < 0 || static_cast<size_t>(index) >= slots.size()) {
    throw Error("VisualMap", "feature index " + std::to_string(index) + " out of range in keyframe " +
                                 std::to_string(keyframe));
  }
  if (slots[index] != -1) {
    throw Error("VisualMap", "feature " + std::to_string(index) + " of keyframe " + std::to_string(keyframe) +
                                 " already observes landmark " + std::to_string(slots[index]));
  }
  for (const Observation& o : landmark.observations) {
    if (o.keyframe == keyframe) {
      throw Error("VisualMap", "landmark " + std::to_string(landmark.id) + " is already observed by keyframe " +
                                   std::to_string(keyframe));
    }
  }
  for (const Observation& o : landmark.observations) covisibility_.addWeight(keyframe, o.keyframe, 1);
  landmark.observations.push_back({keyframe, index});
  slots[index] = landmark.id;
}

template <typename Landmark>
void VisualMap::removeObservation(Landmark& landmark, std::vector<int> Keyframe::*table, int keyframe) {
  auto& obs = landmark.observations;
  const auto it = std::find_if(obs.begin(), obs.end(), [&](const Observation& o) { return o.keyframe == keyframe; });
  if (it == obs.end()) return;
  (find(keyframes_, keyframe, "keyframe").*table)[it->index] = -1;
  obs.erase(it);
  for (const Observation& o : obs) covisibility_.addWeight(keyframe, o.keyframe, -1);
}

void VisualMap::addPointObservation(int point, int keyframe, int index) {
  PointLandmark& p = findById(point_by_id_, point, "point");
  addObservation(p, &Keyframe::point_landmark, keyframe, index);
  updateDescriptor(p);
}

// ORB-SLAM's distinctive descriptor (Mur-Artal et al. 2015, Sec. III-C): of
// the keyframes' descriptors of the point, the one whose median Hamming
// distance to the others is least, so that the point stays matchable as
// the views of it change (the first view's descriptor drifts away from
// later ones with scale and viewing angle).
void VisualMap::updateDescriptor(PointLandmark& point) const {
  std::vector<const uint8_t*> rows;
  for (const Observation& o : point.observations) {
    const cv::Mat& descriptors = find(keyframes_, o.keyframe, "keyframe").features.descriptors;
    if (o.index < descriptors.rows && descriptors.cols == 32 && descriptors.type() == CV_8U)
      rows.push_back(descriptors.ptr<uint8_t>(o.index));
  }
  if (rows.size() < 3) return;  // with two, neither is more central: keep the one the point has
  std::vector<int> distances(rows.size());
  int best_median = std::numeric_limits<int>::max();
  const uint8_t* best = nullptr;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (std::size_t j = 0; j < rows.size(); ++j) distances[j] = hammingDistance256(rows[i], rows[j]);
    const auto middle = distances.begin() + static_cast<std::ptrdiff_t>((rows.size() - 1) / 2);
    std::nth_element(distances.begin(), middle, distances.end());
    if (*middle < best_median) {
      best_median = *middle;
      best = rows[i];
    }
  }
  // A fresh buffer: copies of the map share their landmarks' descriptors.
  point.descriptor = cv::Mat(1, 32, CV_8U, const_cast<uint8_t*>(best)).clone();
}

void VisualMap::addLineObservation(int line, int keyframe, int index) {
  addObservation(findById(line_by_id_, line, "line"), &Keyframe::line_landmark, keyframe, index);
}
void VisualMap::removePointObservation(int point, int keyframe) {
  removeObservation(findById(point_by_id_, point, "point"), &Keyframe::point_landmark, keyframe);
}
void VisualMap::removeLineObservation(int line, int keyframe) {
  removeObservation(findById(line_by_id_, line, "line"), &Keyframe::line_landmark, keyframe);
}

void VisualMap::replacePoint(int from, int into) {
  if (from == into) return;
  const std::vector<Observation> observations = findById(point_by_id_, from, "point").observations;
  PointLandmark& target = findById(point_by_id_, into, "point");
  for (const Observation& o : observations) {
    removePointObservation(from, o.keyframe);
    const bool seen = std::any_of(target.observations.begin(), target.observations.end(),
                                  [&](const Observation& t) { return t.keyframe == o.keyframe; });
    if (!seen) addObservation(target, &Keyframe::point_landmark, o.keyframe, o.index);
  }
  updateDescriptor(target);  // once, over all the views it gained
  erase(points_, point_by_id_, from);
}

void VisualMap::removePoint(int point) {
  PointLandmark& p = findById(point_by_id_, point, "point");
  while (!p.observations.empty()) removePointObservation(point, p.observations.back().keyframe);
  erase(points_, point_by_id_, point);
}

void VisualMap::removeLine(int line) {
  LineLandmark& l = findById(line_by_id_, line, "line");
  while (!l.observations.empty()) removeLineObservation(line, l.observations.back().keyframe);
  erase(lines_, line_by_id_, line);
}

bool VisualMap::hasPoint(int id) const { return alive(point_by_id_, id); }
bool VisualMap::hasLine(int id) const { return alive(line_by_id_, id); }

void VisualMap::removeKeyframe(int keyframe) {
  const Keyframe& kf = find(keyframes_, keyframe, "keyframe");
  if (const int parent = parentFor(keyframe); parent >= 0)
    removed_[keyframe] = {parent, keyframes_.at(parent).T_camera_world * kf.T_camera_world.inverse()};
  const std::vector<int> points = kf.point_landmark, lines = kf.line_landmark;
  for (const int p : points)
    if (p >= 0) removePointObservation(p, keyframe);
  for (const int l : lines)
    if (l >= 0) removeLineObservation(l, keyframe);
  covisibility_.removeNode(keyframe);
  keyframes_.erase(keyframe);
}

int VisualMap::parentFor(int keyframe) const {
  const std::vector<int> covisible = covisibility_.neighbours(keyframe);
  if (!covisible.empty()) return covisible.front();
  const auto it = keyframes_.find(keyframe);
  if (it != keyframes_.begin()) return std::prev(it)->first;
  const auto newer = std::next(it);
  return newer != keyframes_.end() ? newer->first : -1;
}

std::optional<Eigen::Isometry3d> VisualMap::keyframePose(int keyframe) const {
  Eigen::Isometry3d T_keyframe_current = Eigen::Isometry3d::Identity();
  // Parents are alive when a child is removed, so each step leads to a
  // keyframe removed later or alive: the chain ends.
  for (int id = keyframe;;) {
    if (const auto alive = keyframes_.find(id); alive != keyframes_.end())
      return T_keyframe_current * alive->second.T_camera_world;
    const auto gone = removed_.find(id);
    if (gone == removed_.end()) return std::nullopt;
    T_keyframe_current = T_keyframe_current * gone->second.T_parent_keyframe.inverse();
    id = gone->second.parent;
  }
}

void VisualMap::setFusionDirection(int line, const Eigen::Vector3d& d_fu) {
  if (!d_fu.allFinite() || !(d_fu.norm() > 0.0)) throw Error("VisualMap", "fusion direction must be finite and non-zero");
  findById(line_by_id_, line, "line").fusion_direction = d_fu.normalized();
}

void VisualMap::setKeypointDepths(int keyframe, std::vector<double> depths) {
  Keyframe& k = find(keyframes_, keyframe, "keyframe");
  if (depths.size() != k.features.keypoints.size()) {
    throw Error("VisualMap", "keyframe " + std::to_string(keyframe) + " has " +
                                 std::to_string(k.features.keypoints.size()) + " keypoints but " +
                                 std::to_string(depths.size()) + " keypoint depths were given");
  }
  for (double& z : depths)
    if (!std::isfinite(z) || !(z > 0.0)) z = std::numeric_limits<double>::quiet_NaN();
  k.keypoint_depth = std::move(depths);
}

void VisualMap::setOdometryPose(int keyframe, const Eigen::Isometry3d& T_odom_camera) {
  Keyframe& k = find(keyframes_, keyframe, "keyframe");
  if (!isRigidTransform(T_odom_camera))
    throw Error("VisualMap", "the odometry pose of keyframe " + std::to_string(keyframe) + " is not a rigid transform");
  k.T_odom_camera = T_odom_camera;
  if (!T_world_odom_) T_world_odom_ = k.T_camera_world.inverse() * T_odom_camera.inverse();
}

std::optional<Eigen::Isometry3d> VisualMap::odometryPrior(int keyframe) const {
  const Keyframe& k = find(keyframes_, keyframe, "keyframe");
  if (!k.T_odom_camera || !T_world_odom_) return std::nullopt;
  return (*T_world_odom_ * *k.T_odom_camera).inverse();
}

Keyframe& VisualMap::keyframe(int id) { return find(keyframes_, id, "keyframe"); }
const Keyframe& VisualMap::keyframe(int id) const { return find(keyframes_, id, "keyframe"); }
PointLandmark& VisualMap::point(int id) { return findById(point_by_id_, id, "point"); }
const PointLandmark& VisualMap::point(int id) const { return findById(point_by_id_, id, "point"); }
LineLandmark& VisualMap::line(int id) { return findById(line_by_id_, id, "line"); }
const LineLandmark& VisualMap::line(int id) const { return findById(line_by_id_, id, "line"); }

std::vector<int> VisualMap::localWindow(int keyframe, size_t n) const {
  if (!hasKeyframe(keyframe)) throw Error("VisualMap", "unknown keyframe id " + std::to_string(keyframe));
  std::vector<int> window{keyframe};
  if (n <= 1) return window;
  for (const int id : covisibility_.bestNeighbours(keyframe, n - 1)) window.push_back(id);
  return window;
}

double medianSceneDepth(const VisualMap& map, int keyframe) {
  const Keyframe& k = map.keyframe(keyframe);
  std::vector<double> depths;
  for (const int p : k.point_landmark) {
    if (map.hasPoint(p)) depths.push_back((k.T_camera_world * map.point(p).p_world).z());
  }
  return upperMedian(std::move(depths)).value_or(0.0);
}

std::optional<double> firstSeen(const VisualMap& map, const std::vector<Observation>& observations) {
  if (observations.empty()) return std::nullopt;
  return map.keyframe(observations.front().keyframe).timestamp;
}

std::optional<double> medianFirstSeen(const VisualMap& map, const std::vector<int>& points) {
  std::vector<double> times;
  for (const int id : points) {
    if (!map.hasPoint(id)) continue;
    if (const std::optional<double> t = firstSeen(map, map.point(id).observations)) times.push_back(*t);
  }
  return upperMedian(std::move(times));
}

}  // namespace lvslam::visual
