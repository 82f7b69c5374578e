#pragma once
// Guided matching: map points projected with a predicted pose, matched to keypoints nearby
// (docs/method.md#matching-and-pose, ORB-SLAM2's SearchByProjection).
#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/camera.h"
#include "core/settings/matcher_settings.h"
#include "features/frame_features.h"
#include "features/keypoint_grid.h"

namespace slamkit {

struct MapPointSet {
  std::vector<Eigen::Vector3d> points_w;  // world coordinates
  cv::Mat descriptors;                    // CV_8U, one 32-byte row per point
  std::vector<int> octaves;               // level each was observed at; empty = unknown
};

struct ProjectionMatch {
  int point = -1;     // index into MapPointSet
  int keypoint = -1;  // index into FrameFeatures
  int distance = 0;   // Hamming
};

// Projects each point with T_w_c (pinhole: keypoints are undistorted) and takes the keypoint
// within projection_radius x level scale (of the point's octave, if known, among keypoints of
// octave +- projection_octave_window) with the smallest Hamming distance, if at most
// projection_max_distance and below projection_ratio x the second best. A keypoint claimed by
// several points goes to the closest descriptor (then the lower point index). Sorted by point.
// `grid` must be built from frame.undistorted.
std::vector<ProjectionMatch> match_by_projection(const MapPointSet& points,
                                                 const Eigen::Isometry3d& T_w_c,
                                                 const Camera& camera, const FrameFeatures& frame,
                                                 const KeypointGrid& grid,
                                                 const MatcherSettings& settings);

}  // namespace slamkit
