#include "eval/ate.h"

#include <cmath>

#include "core/pose.h"

namespace slamkit::eval {

AteResult compute_ate(const Trajectory& gt, const Trajectory& est,
                      const std::vector<IndexPair>& pairs, const AteOptions& options) {
  std::vector<Eigen::Isometry3d> est_poses, gt_poses;
  est_poses.reserve(pairs.size());
  gt_poses.reserve(pairs.size());
  for (const IndexPair& p : pairs) {
    gt_poses.push_back(gt[p.first].T_w_c);
    est_poses.push_back(est[p.second].T_w_c);
  }
  AteResult r;
  r.alignment = align(est_poses, gt_poses, options.align, options.align_first);
  for (size_t k = 0; k < pairs.size(); ++k) {
    const Eigen::Isometry3d T_aligned = r.alignment.apply(est_poses[k]);
    r.stamps.push_back(est[pairs[k].second].stamp);
    r.est_aligned.push_back(T_aligned.translation());
    r.gt_positions.push_back(gt_poses[k].translation());
    r.trans_errors.push_back((T_aligned.translation() - gt_poses[k].translation()).norm());
    r.rot_errors_deg.push_back(rotation_angle(gt_poses[k].inverse() * T_aligned) * 180.0 / M_PI);
  }
  r.trans = compute_stats(r.trans_errors);
  r.rot_deg = compute_stats(r.rot_errors_deg);
  return r;
}

Trajectory apply_alignment(const Trajectory& est, const Alignment& alignment) {
  std::vector<StampedPose> poses;
  poses.reserve(est.size());
  for (const StampedPose& p : est.poses()) poses.push_back({p.stamp, alignment.apply(p.T_w_c)});
  return Trajectory(std::move(poses));
}

}  // namespace slamkit::eval
