#include "optimization/map_adjustment.h"

#include <algorithm>
#include <map>

namespace slamkit {
namespace {

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

MapBaJob MapBaJob::local_window(const Map& map, int keyframe, const Camera& camera,
                                const OptimizationSettings& settings) {
  std::vector<int> window = {keyframe};
  for (int k : map.best_covisible(keyframe, settings.local.max_covisible_keyframes))
    window.push_back(k);
  return MapBaJob(map, window, camera, settings, true);
}

MapBaJob MapBaJob::whole_map(const Map& map, const Camera& camera,
                             const OptimizationSettings& settings) {
  std::vector<int> all(map.keyframes().size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = int(k);
  return MapBaJob(map, all, camera, settings, false);
}

// Every observation of the free keyframes' points; keyframes observing one of them but not
// free are added as fixed (local BA's rule).
MapBaJob::MapBaJob(const Map& map, const std::vector<int>& free_keyframes, const Camera& camera,
                   const OptimizationSettings& settings, bool local)
    : intrinsics_{camera.fx, camera.fy, camera.cx, camera.cy}, settings_(settings), local_(local) {
  std::map<int, int> pose_of;
  auto add_pose = [&](int keyframe, bool fixed) {
    const auto [it, added] = pose_of.emplace(keyframe, int(keyframes_.size()));
    if (!added) return it->second;
    keyframes_.push_back(keyframe);
    problem_.T_c_w.push_back(map.keyframe(keyframe).T_c_w);
    problem_.pose_fixed.push_back(fixed || keyframe == 0);  // keyframe 0 holds the gauge
    return it->second;
  };
  for (int k : free_keyframes) add_pose(k, false);
  const PyramidGeometry& pyramid = map.pyramid();
  for (int id : good_points_of(map, free_keyframes)) {
    const MapPoint& p = map.point(id);
    const int index = int(points_.size());
    points_.push_back(id);
    problem_.p_w.push_back(p.p_w);
    for (const Observation& o : p.observations) {
      const Keyframe& k = map.keyframe(o.keyframe);
      BaObservation b;
      b.pose = add_pose(o.keyframe, true);
      b.point = index;
      b.uv = k.undistorted[size_t(o.keypoint)];
      b.depth = k.depths[size_t(o.keypoint)];
      b.sigma = pyramid.scale(k.keypoints[size_t(o.keypoint)].octave);
      problem_.observations.push_back(b);
      links_.push_back({o.keyframe, id});
    }
  }
}

void MapBaJob::solve() {
  report_ = local_ ? local_bundle_adjustment(problem_, intrinsics_, settings_.residual,
                                             settings_.local)
                   : global_bundle_adjustment(problem_, intrinsics_, settings_.residual,
                                              settings_.global);
}

MapAdjustment MapBaJob::apply(Map& map) const {
  MapAdjustment result;
  result.report = report_;
  result.points = int(points_.size());
  result.observations = int(problem_.observations.size());
  for (bool fixed : problem_.pose_fixed) (fixed ? result.fixed_keyframes : result.free_keyframes)++;
  if (!report_.solved) return result;
  for (size_t i = 0; i < keyframes_.size(); ++i)
    if (!problem_.pose_fixed[i]) map.set_keyframe_pose(keyframes_[i], problem_.T_c_w[i].inverse());
  for (size_t i = 0; i < points_.size(); ++i) map.set_point_position(points_[i], problem_.p_w[i]);
  for (size_t i = 0; i < report_.outlier.size(); ++i)
    if (report_.outlier[i]) {
      map.erase_observation(links_[i].point, links_[i].keyframe);
      ++result.removed_observations;
    }
  for (int id : points_)
    if (!map.point(id).bad) map.update_point_geometry(id);
  return result;
}

MapAdjustment adjust_local_window(Map& map, int keyframe, const Camera& camera,
                                  const OptimizationSettings& settings) {
  MapBaJob job = MapBaJob::local_window(map, keyframe, camera, settings);
  job.solve();
  return job.apply(map);
}

MapAdjustment adjust_whole_map(Map& map, const Camera& camera,
                               const OptimizationSettings& settings) {
  MapBaJob job = MapBaJob::whole_map(map, camera, settings);
  job.solve();
  return job.apply(map);
}

}  // namespace slamkit
