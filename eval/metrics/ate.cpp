#include "eval/metrics/ate.h"

#include <cmath>

#include "core/pose.h"
#include "eval/metrics/association.h"

namespace slamkit::eval {

AteResult compute_ate(const Trajectory& gt, const Trajectory& est,
                      const std::vector<IndexPair>& pairs, const AteOptions& options,
                      const std::string& gt_name, const std::string& est_name) {
  AteResult r;
  r.alignment = align(gt, est, pairs, options.align, options.align_first, gt_name, est_name);
  r.stamps.reserve(pairs.size());
  r.est_aligned.reserve(pairs.size());
  r.gt_positions.reserve(pairs.size());
  r.trans_errors.reserve(pairs.size());
  r.rot_errors_deg.reserve(pairs.size());
  for (const IndexPair& p : pairs) {
    const Eigen::Isometry3d T_aligned = r.alignment.apply(est.pose(p.second));
    const Eigen::Isometry3d T_gt = gt.pose(p.first);
    r.stamps.push_back(est.stamp(p.second));
    r.est_aligned.push_back(T_aligned.translation());
    r.gt_positions.push_back(T_gt.translation());
    r.trans_errors.push_back((T_aligned.translation() - T_gt.translation()).norm());
    r.rot_errors_deg.push_back(rotation_angle(T_gt.inverse() * T_aligned) * 180.0 / M_PI);
  }
  r.trans = compute_stats(r.trans_errors);
  r.rot_deg = compute_stats(r.rot_errors_deg);
  return r;
}

Trajectory apply_alignment(const Trajectory& est, const Alignment& alignment) {
  if (est.keeps_rotations_as_written()) {
    // A KITTI estimate's near-rotations are moved as the matrices they are, so that each is
    // written as its unit quaternion (Trajectory::orientation), as any pose is.
    std::vector<Eigen::Vector3d> positions(est.size());
    std::vector<Eigen::Matrix3d> rotations(est.size());
    for (size_t i = 0; i < est.size(); ++i) {
      const Eigen::Isometry3d moved = alignment.apply(est.pose(i));
      positions[i] = moved.translation();
      rotations[i] = moved.linear();
    }
    return Trajectory(est.stamps(), std::move(positions), std::move(rotations));
  }
  Trajectory out;
  out.reserve(est.size());
  for (size_t i = 0; i < est.size(); ++i) out.push_back(est.stamp(i), alignment.apply(est.pose(i)));
  return out;
}

double ate_rmse(const Trajectory& gt, const Trajectory& est, const std::string& gt_name,
                const std::string& est_name) {
  const AssociationOptions options;
  const std::vector<IndexPair> pairs = associate(gt, est, options);
  require_enough_pairs(pairs.size(), gt, est, gt_name, est_name, options);
  return compute_ate(gt, est, pairs, AteOptions{}, gt_name, est_name).trans.rmse;
}

}  // namespace slamkit::eval
