#pragma once
// The share of ORB matches between two frames that one rigid motion explains: matches of the
// project's own extractor and matcher, judged by a RANSAC 3D-2D pose fit on the first frame's
// depth.
#include <cmath>
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.h"
#include "core/settings/matcher_settings.h"
#include "core/settings/orb_settings.h"
#include "features/frame_features.h"

namespace slamkit::stats {

struct MatchInlierSettings {
  OrbSettings orb;
  MatcherSettings matcher;
  // Pixels: the tracker's 95% chi-square bound on a 2D reprojection error (chi2_2d = 5.991).
  double threshold = std::sqrt(5.991);
  int iterations = 500;
  size_t min_correspondences = 8;  // fewer and the pair is not fitted
};

struct PairInliers {
  size_t matches = 0;          // descriptor matches
  size_t correspondences = 0;  // of which the first frame has depth: the pose fit's input
  size_t inliers = 0;
  bool fitted = false;  // enough correspondences and RANSAC found a pose
  double share() const { return correspondences ? double(inliers) / double(correspondences) : 0.0; }
};

// Inliers of cv::solvePnPRansac among 3D points (first camera) and their ideal (undistorted)
// pixels in the second image; 0 when RANSAC finds no pose.
size_t pose_inliers(const std::vector<cv::Point3f>& points, const std::vector<cv::Point2f>& pixels,
                    const Camera& camera, const MatchInlierSettings& settings);

// Matches the features of frame a to frame b's and fits b's pose to a's matched points (from
// a's depth, CV_32F metres).
PairInliers match_inliers(const FrameFeatures& a, const cv::Mat& depth_a, const FrameFeatures& b,
                          const Camera& camera, const MatchInlierSettings& settings);

}  // namespace slamkit::stats
