#include "optimization/map_adjustment.h"

#include <algorithm>

namespace slamkit {
namespace {

int good_point_count(const Map& map, int keyframe) {
  int count = 0;
  for (int id : map.keyframe(keyframe).point_ids) count += id >= 0 && !map.point(id).bad;
  return count;
}

// The keyframes that may move: enough points to fix a pose.
std::vector<int> constrained(const Map& map, const std::vector<int>& keyframes,
                             const OptimizationSettings& settings) {
  std::vector<int> kept;
  for (int k : keyframes)
    if (good_point_count(map, k) >= settings.min_keyframe_points) kept.push_back(k);
  return kept;
}

// The keyframes outside the problem (`pose_of` -1) observing `points`, most observations
// first (then by index), at most `limit` of them (0 = all).
std::vector<int> fixed_observers(const Map& map, const std::vector<int>& points,
                                 const std::vector<int>& pose_of, int limit) {
  std::vector<int> shared(pose_of.size(), 0);
  for (int id : points)
    for (const Observation& o : map.point(id).observations)
      if (pose_of[size_t(o.keyframe)] < 0) ++shared[size_t(o.keyframe)];
  std::vector<std::pair<int, int>> ranked;  // (-shared, keyframe)
  for (size_t k = 0; k < shared.size(); ++k)
    if (shared[k] > 0) ranked.push_back({-shared[k], int(k)});
  std::sort(ranked.begin(), ranked.end());
  if (limit > 0 && ranked.size() > size_t(limit)) ranked.resize(size_t(limit));
  std::vector<int> keyframes;
  for (const auto& [negative_count, k] : ranked) keyframes.push_back(k);
  return keyframes;
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

MapBaJob MapBaJob::local_window(const Map& map, int keyframe, const Camera& camera,
                                const OptimizationSettings& settings) {
  std::vector<int> window = {keyframe};
  for (int k : map.best_covisible(keyframe, settings.local_ba.max_covisible_keyframes))
    window.push_back(k);
  return MapBaJob(map, constrained(map, window, settings), camera, settings, true);
}

MapBaJob MapBaJob::whole_map(const Map& map, const Camera& camera,
                             const OptimizationSettings& settings) {
  std::vector<int> all(map.keyframes().size());
  for (size_t k = 0; k < all.size(); ++k) all[k] = int(k);
  return MapBaJob(map, constrained(map, all, settings), camera, settings, false);
}

// Every observation of the free keyframes' points by a keyframe in the problem. Local BA adds
// the other keyframes observing them as fixed; global BA leaves them out.
MapBaJob::MapBaJob(const Map& map, const std::vector<int>& free_keyframes, const Camera& camera,
                   const OptimizationSettings& settings, bool local)
    : intrinsics_{camera.fx, camera.fy, camera.cx, camera.cy}, settings_(settings), local_(local) {
  // Each keyframe's pose in the problem, -1 if none: indexed, as it is looked up for every
  // observation of every point in the window.
  std::vector<int> pose_of(map.keyframes().size(), -1);
  auto add_pose = [&](int keyframe, bool fixed) {
    if (pose_of[size_t(keyframe)] >= 0) return;
    pose_of[size_t(keyframe)] = int(keyframes_.size());
    keyframes_.push_back(keyframe);
    problem_.T_c_w.push_back(map.keyframe(keyframe).T_c_w);
    problem_.pose_fixed.push_back(fixed || keyframe == 0);  // keyframe 0 holds the gauge
  };
  for (int k : free_keyframes) add_pose(k, false);
  const std::vector<int> points = good_points_of(map, free_keyframes);
  if (local) {
    for (int k : fixed_observers(map, points, pose_of, settings.local_ba.max_fixed_keyframes))
      add_pose(k, true);
  }
  const PyramidGeometry& pyramid = map.pyramid();
  for (int id : points) {
    const MapPoint& p = map.point(id);
    const int index = int(points_.size());
    points_.push_back(id);
    problem_.p_w.push_back(p.p_w);
    for (const Observation& o : p.observations) {
      const int pose = pose_of[size_t(o.keyframe)];
      if (pose < 0) continue;
      const Keyframe& k = map.keyframe(o.keyframe);
      BaObservation b;
      b.pose = pose;
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
                                             settings_.local_ba)
                   : global_bundle_adjustment(problem_, intrinsics_, settings_.residual,
                                              settings_.global_ba);
}

MapAdjustment MapBaJob::apply(Map& map) const {
  MapAdjustment result;
  result.report = report_;
  result.points = int(points_.size());
  result.observations = int(problem_.observations.size());
  for (bool fixed : problem_.pose_fixed) (fixed ? result.fixed_keyframes : result.free_keyframes)++;
  if (!report_.solved) return result;
  std::vector<Eigen::Isometry3d> T_w_c_before;
  for (const Keyframe& k : map.keyframes()) T_w_c_before.push_back(k.T_w_c);
  for (size_t i = 0; i < keyframes_.size(); ++i)
    if (!problem_.pose_fixed[i]) map.set_keyframe_pose(keyframes_[i], problem_.T_c_w[i].inverse());
  for (size_t i = 0; i < points_.size(); ++i) map.set_point_position(points_[i], problem_.p_w[i]);
  for (size_t i = 0; i < report_.outlier.size(); ++i)
    if (report_.outlier[i]) {
      map.erase_observation(links_[i].point, links_[i].keyframe);
      ++result.removed_observations;
    }
  if (!local_) carry_along(map, T_w_c_before);
  for (int id : points_)
    if (!map.point(id).bad) map.update_point_geometry(id);
  return result;
}

void MapBaJob::carry_along(Map& map, const std::vector<Eigen::Isometry3d>& T_w_c_before) const {
  std::vector<bool> adjusted(map.keyframes().size(), false);
  for (int k : keyframes_) adjusted[size_t(k)] = true;
  // A parent is older than its children, so walking by index corrects parents first.
  for (size_t k = 0; k < adjusted.size(); ++k) {
    const int parent = map.keyframe(int(k)).parent;
    if (adjusted[k] || parent < 0) continue;
    map.set_keyframe_pose(int(k), map.keyframe(parent).T_w_c *
                                      T_w_c_before[size_t(parent)].inverse() * T_w_c_before[k]);
  }
  std::vector<bool> in_problem(size_t(map.num_point_ids()), false);
  for (int id : points_) in_problem[size_t(id)] = true;
  for (size_t id = 0; id < in_problem.size(); ++id) {
    const MapPoint& p = map.point(int(id));
    if (in_problem[id] || p.bad) continue;
    const int r = p.reference_keyframe;
    map.set_point_position(int(id),
                           map.keyframe(r).T_w_c * (T_w_c_before[size_t(r)].inverse() * p.p_w));
  }
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
