#include "lvslam/visual/initialize/two_view_initializer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <opencv2/calib3d.hpp>
#include <opencv2/core/eigen.hpp>

#include "lvslam/core/error.h"
#include "lvslam/visual/initialize/two_view_geometry.h"

namespace lvslam::visual {

namespace {

std::vector<cv::Point2d> toCv(const std::vector<Eigen::Vector2d>& v) {
  std::vector<cv::Point2d> out;
  out.reserve(v.size());
  for (const auto& p : v) out.emplace_back(p.x(), p.y());
  return out;
}

Eigen::Matrix3d toEigen3(const cv::Mat& m) {
  Eigen::Matrix3d e;
  cv::cv2eigen(m, e);
  return e;
}

std::vector<MotionHypothesis> homographyHypotheses(const cv::Mat& H, const cv::Mat& K) {
  std::vector<cv::Mat> Rs, ts, normals;
  cv::decomposeHomographyMat(H, K, Rs, ts, normals);
  std::vector<MotionHypothesis> out;
  for (size_t i = 0; i < Rs.size(); ++i) {
    Eigen::Vector3d t;
    cv::cv2eigen(ts[i], t);
    out.push_back({toEigen3(Rs[i]), t});
  }
  return out;
}

std::vector<MotionHypothesis> essentialHypotheses(const cv::Mat& E) {
  cv::Mat R1, R2, t;
  cv::decomposeEssentialMat(E, R1, R2, t);
  Eigen::Vector3d te;
  cv::cv2eigen(t, te);
  return {{toEigen3(R1), te}, {toEigen3(R1), -te}, {toEigen3(R2), te}, {toEigen3(R2), -te}};
}

// hint depth / triangulated depth over hinted, triangulated matches.
std::vector<double> hintRatios(const std::vector<DepthHint>& hints, const std::vector<TwoViewMatch>& matches,
                               const MotionHypothesisCheck& check) {
  std::vector<double> ratios;
  for (const DepthHint& h : hints) {
    if (!(h.depth > 0.0) || !std::isfinite(h.depth)) continue;
    for (size_t i = 0; i < matches.size(); ++i) {
      if (matches[i].index1 == h.index1 && check.triangulated[i]) ratios.push_back(h.depth / check.points[i].z());
    }
  }
  return ratios;
}

double median(std::vector<double> v) {
  const auto mid = v.begin() + v.size() / 2;
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Median absolute deviation of log(ratio): 0 when the hints agree with the
// hypothesis' structure up to one scale, large when the structure is wrong.
double hintSpread(const std::vector<double>& ratios) {
  std::vector<double> logs;
  for (const double r : ratios) logs.push_back(std::log(r));
  const double m = median(logs);
  for (double& l : logs) l = std::abs(l - m);
  return median(logs);
}

// Index of the hypothesis the depth hints single out among the ambiguous
// ones (the two-fold planar ambiguity, which two views alone cannot resolve).
std::optional<size_t> resolveWithHints(const std::vector<size_t>& contenders,
                                       const std::vector<MotionHypothesisCheck>& checks,
                                       const std::vector<DepthHint>& hints, const std::vector<TwoViewMatch>& matches,
                                       int min_hints) {
  std::vector<std::pair<double, size_t>> spreads;
  for (const size_t c : contenders) {
    const std::vector<double> ratios = hintRatios(hints, matches, checks[c]);
    if (static_cast<int>(ratios.size()) < min_hints) return std::nullopt;
    spreads.emplace_back(hintSpread(ratios), c);
  }
  std::sort(spreads.begin(), spreads.end());
  constexpr double kConsistent = 0.05;  // hints agree within ~5 %
  if (spreads[0].first > kConsistent || spreads[1].first < 2.0 * spreads[0].first) return std::nullopt;
  return spreads[0].second;
}

double medianDepth(const MotionHypothesisCheck& check) {
  std::vector<double> z;
  for (size_t i = 0; i < check.points.size(); ++i) {
    if (check.triangulated[i]) z.push_back(check.points[i].z());
  }
  return median(std::move(z));
}

bool gatherMatches(const std::vector<Eigen::Vector2d>& points1, const std::vector<Eigen::Vector2d>& points2,
                   const std::vector<TwoViewMatch>& matches, std::vector<Eigen::Vector2d>& x1,
                   std::vector<Eigen::Vector2d>& x2) {
  for (const TwoViewMatch& m : matches) {
    if (m.index1 < 0 || static_cast<size_t>(m.index1) >= points1.size() || m.index2 < 0 ||
        static_cast<size_t>(m.index2) >= points2.size()) {
      throw Error("TwoViewInitializer", "match (" + std::to_string(m.index1) + ", " + std::to_string(m.index2) +
                                            ") is out of range");
    }
    if (!points1[m.index1].allFinite() || !points2[m.index2].allFinite()) return false;
    x1.push_back(points1[m.index1]);
    x2.push_back(points2[m.index2]);
  }
  return true;
}

}  // namespace

// Homography and essential matrix in parallel; R_H = S_H / (S_H + S_F) picks one.
std::optional<TwoViewInitializer::ModelSelection> TwoViewInitializer::selectModel(
    const Eigen::Matrix3d& K, const std::vector<Eigen::Vector2d>& x1, const std::vector<Eigen::Vector2d>& x2,
    const TwoViewInitializerConfig& config) {
  cv::Mat K_cv;
  cv::eigen2cv(K, K_cv);
  const std::vector<cv::Point2d> p1 = toCv(x1), p2 = toCv(x2);
  const double sigma = config.sigma_px;
  // USAC_ACCURATE polishes the model on all inliers (plain RANSAC returns a minimal-sample fit).
  const cv::Mat H = cv::findHomography(p1, p2, cv::USAC_ACCURATE, std::sqrt(5.991) * sigma, cv::noArray(), 2000, 0.999);
  const cv::Mat E = cv::findEssentialMat(p1, p2, K_cv, cv::USAC_ACCURATE, 0.999, sigma);
  if (E.rows != 3 || E.cols != 3) return std::nullopt;  // several solutions stacked or none

  ModelSelection model;
  std::vector<bool> inliers_h, inliers_f;
  const double score_h = H.empty() ? 0.0 : homographyScore(toEigen3(H), x1, x2, sigma, inliers_h);
  const Eigen::Matrix3d F = K.inverse().transpose() * toEigen3(E) * K.inverse();
  const double score_f = fundamentalScore(F, x1, x2, sigma, inliers_f);
  if (!(score_h + score_f > 0.0)) return std::nullopt;
  model.homography = score_h / (score_h + score_f) > config.homography_ratio;
  model.hypotheses = model.homography ? homographyHypotheses(H, K_cv) : essentialHypotheses(E);
  model.inliers = model.homography ? inliers_h : inliers_f;
  return model;
}

TwoViewInitializer::TwoViewInitializer(const TwoViewInitializerConfig& config, const PinholeIntrinsics& intrinsics)
    : config_(config), K_(intrinsics) {
  if (!(config_.sigma_px > 0.0)) throw Error("TwoViewInitializerConfig", "sigma_px must be positive");
  if (config_.min_triangulated < 8) throw Error("TwoViewInitializerConfig", "min_triangulated must be >= 8");
  if (!(K_.fx > 0.0 && K_.fy > 0.0)) throw Error("TwoViewInitializer", "focal lengths must be positive");
}

std::optional<TwoViewInitialization> TwoViewInitializer::initialize(const std::vector<Eigen::Vector2d>& points1,
                                                                    const std::vector<Eigen::Vector2d>& points2,
                                                                    const std::vector<TwoViewMatch>& matches) const {
  std::vector<Eigen::Vector2d> x1, x2;
  if (!gatherMatches(points1, points2, matches, x1, x2)) return std::nullopt;
  if (static_cast<int>(x1.size()) < config_.min_triangulated) return std::nullopt;
  Eigen::Matrix3d K;
  K << K_.fx, 0.0, K_.cx, 0.0, K_.fy, K_.cy, 0.0, 0.0, 1.0;
  const std::optional<ModelSelection> model = selectModel(K, x1, x2, config_);
  if (!model) return std::nullopt;

  std::vector<MotionHypothesisCheck> checks;
  for (const MotionHypothesis& h : model->hypotheses) {
    checks.push_back(checkMotionHypothesis(h.R, h.t, K, x1, x2, model->inliers, config_.sigma_px));
  }
  const std::optional<size_t> chosen = chooseHypothesis(checks, *model, matches);
  if (!chosen) return std::nullopt;
  const MotionHypothesisCheck& best = checks[*chosen];
  if (best.median_parallax_deg < config_.min_parallax_deg) return std::nullopt;
  const int triangulated = static_cast<int>(std::count(best.triangulated.begin(), best.triangulated.end(), true));
  if (triangulated < config_.min_triangulated) return std::nullopt;

  TwoViewInitialization out;
  out.used_homography = model->homography;
  out.median_parallax_deg = best.median_parallax_deg;
  out.num_triangulated = triangulated;
  out.triangulated = best.triangulated;
  const std::vector<double> ratios = hintRatios(hints_, matches, best);
  out.metric = static_cast<int>(ratios.size()) >= config_.min_depth_hints;
  const double scale = out.metric ? median(ratios) : 1.0 / medianDepth(best);
  out.points_c1.resize(best.points.size());
  for (size_t i = 0; i < best.points.size(); ++i) out.points_c1[i] = scale * best.points[i];
  out.T_c2_c1.linear() = model->hypotheses[*chosen].R;
  out.T_c2_c1.translation() = scale * model->hypotheses[*chosen].t;
  return out;
}

std::optional<size_t> TwoViewInitializer::chooseHypothesis(const std::vector<MotionHypothesisCheck>& checks,
                                                           const ModelSelection& model,
                                                           const std::vector<TwoViewMatch>& matches) const {
  std::vector<size_t> order(checks.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return checks[a].num_good > checks[b].num_good; });
  const int best_good = checks[order[0]].num_good;
  const int inlier_count = static_cast<int>(std::count(model.inliers.begin(), model.inliers.end(), true));
  if (best_good < std::max(config_.min_triangulated, static_cast<int>(0.9 * inlier_count))) return std::nullopt;
  const double ambiguity = model.homography ? config_.ambiguity_ratio_homography : config_.ambiguity_ratio_essential;
  std::vector<size_t> contenders;
  for (const size_t i : order) {
    if (checks[i].num_good >= ambiguity * best_good) contenders.push_back(i);
  }
  if (contenders.size() == 1) return contenders[0];
  return resolveWithHints(contenders, checks, hints_, matches, config_.min_depth_hints);
}

}  // namespace lvslam::visual
