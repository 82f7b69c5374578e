#include "eval/sequence_stats/match_inliers.h"

#include <opencv2/calib3d.hpp>

#include "features/descriptor_matcher.h"

namespace slamkit::stats {

size_t pose_inliers(const std::vector<cv::Point3f>& points, const std::vector<cv::Point2f>& pixels,
                    const Camera& camera, const MatchInlierSettings& settings) {
  const cv::Matx33d K(camera.fx, 0, camera.cx, 0, camera.fy, camera.cy, 0, 0, 1);
  cv::Mat rvec, tvec;
  std::vector<int> inliers;
  // Pixels are already undistorted, hence no distortion coefficients. OpenCV's RANSAC seeds
  // its generator the same way on every call, so the count repeats.
  const bool found =
      cv::solvePnPRansac(points, pixels, K, cv::noArray(), rvec, tvec, false, settings.iterations,
                         float(settings.threshold), 0.999, inliers);
  return found ? inliers.size() : 0;
}

PairInliers match_inliers(const FrameFeatures& a, const cv::Mat& depth_a, const FrameFeatures& b,
                          const Camera& camera, const MatchInlierSettings& settings) {
  PairInliers result;
  const std::vector<cv::DMatch> matches =
      match_descriptors(a.descriptors, b.descriptors, settings.matcher);
  result.matches = matches.size();
  std::vector<cv::Point3f> points;
  std::vector<cv::Point2f> pixels;
  for (const cv::DMatch& m : matches) {
    const float z = depth_at(depth_a, a.keypoints[size_t(m.queryIdx)]);
    if (!camera.is_valid_depth(z)) continue;
    const Eigen::Vector3d p = camera.back_project(a.undistorted[size_t(m.queryIdx)], z);
    const Eigen::Vector2d& uv = b.undistorted[size_t(m.trainIdx)];
    points.emplace_back(float(p.x()), float(p.y()), float(p.z()));
    pixels.emplace_back(float(uv.x()), float(uv.y()));
  }
  result.correspondences = points.size();
  if (points.size() < settings.min_correspondences) return result;
  result.inliers = pose_inliers(points, pixels, camera, settings);
  result.fitted = result.inliers > 0;
  return result;
}

}  // namespace slamkit::stats
