#pragma once
// Closed-form rigid alignment of 3D-3D pairs (the paper's closed-form ICP,
// docs/method.md#matching-and-pose) inside RANSAC with the 3-point minimal set.
#include <Eigen/Geometry>
#include <optional>
#include <vector>

#include "core/settings/tracking_settings.h"

namespace slamkit {

enum class RigidFitStatus {
  kOk,
  kTooFewPairs,  // fewer than 3 pairs, or q_prev and q_curr of different sizes
  kDegenerate,   // no non-degenerate sample / inlier set (e.g. all points collinear)
};

struct RigidFit {
  RigidFitStatus status = RigidFitStatus::kTooFewPairs;
  Eigen::Isometry3d T_prev_curr = Eigen::Isometry3d::Identity();  // q_prev ~ T q_curr
  std::vector<bool> inliers;  // one per pair; empty unless status is kOk
  int num_inliers = 0;
  double inlier_rmse = 0;  // metres, |q - T q'| over the inliers
  int iterations = 0;      // RANSAC samples drawn
  bool ok() const { return status == RigidFitStatus::kOk; }
};

// Least-squares rigid transform T with q_prev[i] ~ T q_curr[i] over the listed pairs
// (Umeyama without scale: centroids, SVD of the cross-covariance, reflection fixed).
// nullopt when fewer than 3 pairs or the points are (nearly) collinear.
std::optional<Eigen::Isometry3d> fit_rigid(const std::vector<Eigen::Vector3d>& q_prev,
                                           const std::vector<Eigen::Vector3d>& q_curr,
                                           const std::vector<int>& indices);

// Inlier threshold (metres) for a pair whose previous-frame point has depth z.
double ransac_threshold(const RansacSettings& settings, double z);

// RANSAC over the pairs (q_prev[i] in the previous camera, q_curr[i] in the current one),
// then a refit on all inliers. Deterministic: the samples come from settings.seed.
// Whether there are enough pairs to use this solver (TrackingSettings::min_pairs_for_svd)
// is the caller's decision.
RigidFit icp_svd_ransac(const std::vector<Eigen::Vector3d>& q_prev,
                        const std::vector<Eigen::Vector3d>& q_curr, const RansacSettings& settings);

}  // namespace slamkit
