#include "loop/loop_neighbourhood.h"

#include <algorithm>
#include <limits>
#include <set>

#include "features/descriptor.h"
#include "features/keypoint_grid.h"
#include "map/point_projection.h"

namespace slamkit {
namespace {

// ORB-SLAM2's projection searches keep points seen at most about 60 degrees off their mean
// viewing direction.
constexpr double kMinViewCos = 0.5;

std::vector<int> neighbourhood_points(const Map& map, int candidate) {
  std::vector<int> group = map.best_covisible(candidate, 0);
  group.insert(group.begin(), candidate);
  std::set<int> points;
  for (int k : group)
    for (int id : map.keyframe(k).point_ids)
      if (id >= 0 && !map.point(id).bad) points.insert(id);
  return {points.begin(), points.end()};
}

}  // namespace

std::vector<LoopPointMatch> match_loop_neighbourhood(const Map& map, int keyframe, int candidate,
                                                     const Eigen::Isometry3d& T_w_keyframe,
                                                     const std::vector<bool>& taken,
                                                     const Camera& camera, double radius,
                                                     int max_distance) {
  const Keyframe& k = map.keyframe(keyframe);
  const KeypointGrid grid(k.undistorted);
  // Per keypoint, the best (distance, point) so far.
  std::vector<std::pair<int, int>> best(k.keypoints.size(),
                                        {std::numeric_limits<int>::max(), -1});
  std::vector<int> nearby;
  const Eigen::Isometry3d T_keyframe_w = T_w_keyframe.inverse();
  for (int id : neighbourhood_points(map, candidate)) {
    const MapPoint& p = map.point(id);
    const auto projection =
        project_point(map, p, T_keyframe_w, T_w_keyframe.translation(), camera, kMinViewCos);
    if (!projection) continue;
    grid.within(projection->uv, radius * map.pyramid().scale(projection->octave), nearby);
    int closest = std::numeric_limits<int>::max(), closest_keypoint = -1;
    for (int c : nearby) {
      const int level = k.keypoints[size_t(c)].octave;
      if (taken[size_t(c)] || level < projection->octave - 1 || level > projection->octave)
        continue;
      const int d = descriptor_distance(p.descriptor.data(), k.descriptors.ptr<uchar>(c));
      if (d < closest || (d == closest && c < closest_keypoint)) closest = d, closest_keypoint = c;
    }
    if (closest_keypoint < 0 || closest > max_distance) continue;
    best[size_t(closest_keypoint)] = std::min(best[size_t(closest_keypoint)], {closest, id});
  }
  std::vector<LoopPointMatch> matches;
  for (size_t c = 0; c < best.size(); ++c)
    if (best[c].second >= 0) matches.push_back({int(c), best[c].second});
  return matches;
}

}  // namespace slamkit
