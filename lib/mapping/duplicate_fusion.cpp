#include "mapping/duplicate_fusion.h"

#include <algorithm>
#include <limits>

#include "features/descriptor.h"
#include "features/keypoint_grid.h"
#include "map/point_projection.h"

namespace slamkit {

std::vector<int> fuse_into_keyframe(Map& map, int keyframe, const std::vector<int>& points,
                                    const Camera& camera, const FusionGates& gates) {
  const Keyframe& k = map.keyframe(keyframe);
  const KeypointGrid grid(k.undistorted);
  std::vector<int> candidates;
  std::vector<int> gained;
  for (int id : points) {
    const MapPoint& p = map.point(id);
    if (p.bad || std::any_of(p.observations.begin(), p.observations.end(),
                             [&](const Observation& o) { return o.keyframe == keyframe; }))
      continue;
    const auto projection = project_point(map, p, k.T_c_w, k.centre(), camera, gates.min_view_cos);
    if (!projection) continue;
    const Eigen::Vector2d& uv = projection->uv;
    const int octave = projection->octave;
    const double scale = map.pyramid().scale(octave);
    grid.within(uv, gates.radius * scale, candidates);

    int best = std::numeric_limits<int>::max(), best_keypoint = -1;
    const double predicted_disparity = gates.virtual_bf / projection->p_c.z();
    for (int c : candidates) {
      const int level = k.keypoints[size_t(c)].octave;
      if (level < octave - 1 || level > octave) continue;
      // The reprojection gate: squared error over the level's variance against chi-square.
      const double inv_sigma2 = 1.0 / (map.pyramid().scale(level) * map.pyramid().scale(level));
      double error2 = (k.undistorted[size_t(c)] - uv).squaredNorm();
      const float depth = k.depths[size_t(c)];
      if (depth > 0) {
        const double e = gates.virtual_bf / depth - predicted_disparity;
        if ((error2 + e * e) * inv_sigma2 > gates.chi2_3d) continue;
      } else if (error2 * inv_sigma2 > gates.chi2_2d) {
        continue;
      }
      const int d = descriptor_distance(p.descriptor.data(), k.descriptors.ptr<uchar>(c));
      if (d < best) best = d, best_keypoint = c;
    }
    if (best_keypoint < 0 || best > gates.max_distance) continue;

    const int existing = map.keyframe(keyframe).point_ids[size_t(best_keypoint)];
    if (existing >= 0 && !map.point(existing).bad) {
      // The better-observed point survives (ORB-SLAM2's Replace).
      const bool keep_existing = map.point(existing).num_observations() > p.num_observations();
      const int survivor = keep_existing ? existing : id;
      map.replace_point(keep_existing ? id : existing, survivor);
      gained.push_back(survivor);
    } else {
      map.add_observation(id, keyframe, best_keypoint);
      gained.push_back(id);
    }
  }
  return gained;
}

}  // namespace slamkit
