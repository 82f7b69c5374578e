#include "optimization/map_adjustment.h"

#include <algorithm>
#include <map>

namespace slamkit {
namespace {

// The problem over the chosen keyframes and points, with the index maps to write it back.
struct MapProblem {
  BaProblem problem;
  std::vector<int> keyframes;  // problem pose -> map keyframe
  std::vector<int> points;     // problem point -> map point
  struct Link {
    int keyframe, point;
  };
  std::vector<Link> observed;  // problem observation -> the map's keyframe and point
};

BaIntrinsics intrinsics_of(const Camera& camera) {
  return {camera.fx, camera.fy, camera.cx, camera.cy};
}

// Every observation of `points` by a keyframe that is free or fixed; keyframes observing a
// point but in neither set are added as fixed (local BA's rule).
MapProblem build(const Map& map, const std::vector<int>& free_keyframes,
                 const std::vector<int>& points) {
  MapProblem out;
  std::map<int, int> pose_of;
  auto add_pose = [&](int keyframe, bool fixed) {
    const auto [it, added] = pose_of.emplace(keyframe, int(out.keyframes.size()));
    if (!added) return it->second;
    out.keyframes.push_back(keyframe);
    out.problem.T_c_w.push_back(map.keyframe(keyframe).T_c_w);
    out.problem.pose_fixed.push_back(fixed || keyframe == 0);  // keyframe 0 holds the gauge
    return it->second;
  };
  for (int k : free_keyframes) add_pose(k, false);
  const PyramidGeometry& pyramid = map.pyramid();
  for (int id : points) {
    const MapPoint& p = map.point(id);
    const int index = int(out.points.size());
    out.points.push_back(id);
    out.problem.p_w.push_back(p.p_w);
    for (const Observation& o : p.observations) {
      const Keyframe& k = map.keyframe(o.keyframe);
      BaObservation b;
      b.pose = add_pose(o.keyframe, true);
      b.point = index;
      b.uv = k.undistorted[size_t(o.keypoint)];
      b.depth = k.depths[size_t(o.keypoint)];
      b.sigma = pyramid.scale(k.keypoints[size_t(o.keypoint)].octave);
      out.problem.observations.push_back(b);
      out.observed.push_back({o.keyframe, id});
    }
  }
  return out;
}

MapAdjustment write_back(Map& map, const MapProblem& built, const BaReport& report) {
  MapAdjustment result;
  result.report = report;
  result.points = int(built.points.size());
  result.observations = int(built.problem.observations.size());
  for (size_t i = 0; i < built.keyframes.size(); ++i)
    (built.problem.pose_fixed[i] ? result.fixed_keyframes : result.free_keyframes)++;
  if (!report.solved) return result;
  for (size_t i = 0; i < built.keyframes.size(); ++i)
    if (!built.problem.pose_fixed[i])
      map.set_keyframe_pose(built.keyframes[i], built.problem.T_c_w[i].inverse());
  for (size_t i = 0; i < built.points.size(); ++i)
    map.set_point_position(built.points[i], built.problem.p_w[i]);
  for (size_t i = 0; i < report.outlier.size(); ++i)
    if (report.outlier[i]) {
      map.erase_observation(built.observed[i].point, built.observed[i].keyframe);
      ++result.removed_observations;
    }
  for (int id : built.points)
    if (!map.point(id).bad) map.update_point_geometry(id);
  return result;
}

std::vector<int> good_points_of(const Map& map, const std::vector<int>& keyframes) {
  std::vector<int> ids;
  for (int k : keyframes)
    for (int id : map.keyframe(k).point_ids)
      if (id >= 0 && !map.point(id).bad) ids.push_back(id);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

}  // namespace

MapAdjustment adjust_local_window(Map& map, int keyframe, const Camera& camera,
                                  const OptimizationSettings& settings) {
  std::vector<int> window = {keyframe};
  for (int k : map.best_covisible(keyframe, settings.local.max_covisible_keyframes))
    window.push_back(k);
  MapProblem built = build(map, window, good_points_of(map, window));
  const BaReport report = local_bundle_adjustment(built.problem, intrinsics_of(camera),
                                                  settings.residual, settings.local);
  return write_back(map, built, report);
}

MapAdjustment adjust_whole_map(Map& map, const Camera& camera,
                               const OptimizationSettings& settings) {
  std::vector<int> all(map.keyframes().size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = int(k);
  MapProblem built = build(map, all, good_points_of(map, all));
  const BaReport report = global_bundle_adjustment(built.problem, intrinsics_of(camera),
                                                   settings.residual, settings.global);
  return write_back(map, built, report);
}

}  // namespace slamkit
