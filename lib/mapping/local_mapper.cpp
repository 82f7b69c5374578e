#include "mapping/local_mapper.h"

#include <algorithm>
#include <vector>

#include "core/stopwatch.h"
#include "mapping/duplicate_fusion.h"

namespace slamkit {

LocalMapper::LocalMapper(const Camera& camera, const Settings& settings, Map& map, bool concurrent)
    : camera_(camera),
      settings_(settings),
      map_(map),
      launch_(concurrent ? std::launch::async : std::launch::deferred) {}

int LocalMapper::insert_keyframe(Keyframe keyframe, double motion) {
  Stopwatch watch;
  MappingReport report;
  report.ba_wait_ms = 0;
  {
    Stopwatch wait;
    finish();
    report.ba_wait_ms = wait.lap();
  }
  const int id = map_.add_keyframe(std::move(keyframe));
  report.keyframe = id;
  // The tracked points' descriptors and viewing directions now include this view.
  for (int point : map_.keyframe(id).point_ids)
    if (point >= 0) {
      map_.update_point_descriptor(point);
      map_.update_point_geometry(point);
    }
  report.new_points = create_points(id);
  map_.update_connections(id);
  report.culled_points = cull_recent_points(id);
  if (settings_.mapping.fuse_duplicates) report.fused_points = fuse_duplicates(id);

  const LocalBaSettings& ba = settings_.optimization.local_ba;
  if (ba.enabled && id >= 2 && motion >= ba.min_motion &&
      id % std::max(1, ba.every_keyframes) == 0) {
    pending_ = std::make_unique<MapBaJob>(
        MapBaJob::local_window(map_, id, camera_, settings_.optimization));
    solving_ = std::async(launch_, [job = pending_.get()] { job->solve(); });
  }
  // Part of the back end: the front end alone (`track`, no local BA) keeps every keyframe.
  if (settings_.mapping.cull_keyframes && ba.enabled) cull_around_ = id;
  report.ms = watch.lap();
  reports_.push_back(report);
  return id;
}

void LocalMapper::finish() {
  if (pending_) {
    solving_.get();
    MappingReport& report = reports_.back();  // the keyframe whose BA this is
    report.ba = pending_->apply(map_);
    report.ba_run = report.ba.report.solved;
    pending_.reset();
  }
  // ORB-SLAM2 culls right after local BA; here that is where the BA is applied, so that
  // tracking sees the same map whether BA ran beside it or not.
  if (cull_around_ >= 0) {
    reports_.back().culled_keyframes = cull_redundant_keyframes(cull_around_);
    cull_around_ = -1;
  }
}

int LocalMapper::cull_redundant_keyframes(int keyframe) {
  int culled = 0;
  for (int neighbour : map_.best_covisible(keyframe, 0))  // a copy: culling edits the lists
    if (neighbour != 0 && redundant(neighbour)) {
      map_.cull_keyframe(neighbour);
      ++culled;
    }
  return culled;
}

bool LocalMapper::redundant(int keyframe) const {
  // ORB-SLAM2's KeyFrameCulling test on the keyframe's close points.
  const MappingSettings& s = settings_.mapping;
  const Keyframe& k = map_.keyframe(keyframe);
  int close = 0, seen_elsewhere = 0;
  for (size_t i = 0; i < k.point_ids.size(); ++i) {
    const int id = k.point_ids[i];
    if (id < 0 || map_.point(id).bad || k.depths[i] <= 0 || k.depths[i] > s.culling_max_depth)
      continue;
    ++close;
    const MapPoint& p = map_.point(id);
    if (p.num_observations() <= s.culling_observers) continue;
    int observers = 0;
    for (const Observation& o : p.observations)
      observers += o.keyframe != keyframe &&
                   map_.keyframe(o.keyframe).keypoints[size_t(o.keypoint)].octave <=
                       k.keypoints[i].octave + 1;
    seen_elsewhere += observers >= s.culling_observers;
  }
  return seen_elsewhere > s.culling_redundancy * close;
}

int LocalMapper::create_points(int keyframe) {
  // Landmarks come from depth (the paper's rule): every keypoint with valid depth and no point yet.
  int created = 0;
  const size_t n = map_.keyframe(keyframe).keypoints.size();
  for (size_t i = 0; i < n; ++i) {
    const Keyframe& k = map_.keyframe(keyframe);
    if (k.point_ids[i] >= 0 || k.depths[i] <= 0) continue;
    const Eigen::Vector3d p_w = k.T_w_c * camera_.back_project(k.undistorted[i], k.depths[i]);
    recent_points_.push_back(map_.add_point(p_w, keyframe, static_cast<int>(i)));
    ++created;
  }
  return created;
}

int LocalMapper::cull_recent_points(int keyframe) {
  // ORB-SLAM2's MapPointCulling: points on probation leave the list after 3 keyframes.
  const MappingSettings& s = settings_.mapping;
  int culled = 0;
  std::vector<int> kept;
  for (int id : recent_points_) {
    const MapPoint& p = map_.point(id);
    if (p.bad) continue;
    const int age = keyframe - p.reference_keyframe;
    if (p.found_ratio() < s.min_found_ratio ||
        (age >= s.cull_after_keyframes && p.num_observations() < s.min_observations)) {
      map_.cull_point(id);
      ++culled;
    } else if (age < s.cull_after_keyframes + 1) {
      kept.push_back(id);
    }
  }
  recent_points_ = std::move(kept);
  return culled;
}

int LocalMapper::fuse_duplicates(int keyframe) {
  const MappingSettings& s = settings_.mapping;
  FusionGates gates;
  gates.radius = s.fuse_radius;
  gates.max_distance = s.fuse_max_distance;
  gates.min_view_cos = s.min_view_cos;
  gates.chi2_2d = settings_.optimization.residual.chi2_2d;
  gates.chi2_3d = settings_.optimization.residual.chi2_3d;
  gates.virtual_bf = settings_.optimization.residual.virtual_bf;

  const std::vector<int> targets = map_.best_covisible(keyframe, s.fuse_neighbours);
  auto points_of = [&](int k) {
    std::vector<int> ids;
    for (int id : map_.keyframe(k).point_ids)
      if (id >= 0 && !map_.point(id).bad) ids.push_back(id);
    return ids;
  };
  // The new keyframe's points into each neighbour, then the neighbours' points into it.
  std::vector<int> gained;
  const auto fuse = [&](int target, const std::vector<int>& points) {
    const std::vector<int> ids = fuse_into_keyframe(map_, target, points, camera_, gates);
    gained.insert(gained.end(), ids.begin(), ids.end());
  };
  for (int target : targets) fuse(target, points_of(keyframe));
  std::vector<int> theirs;  // each once, ascending
  for (int target : targets) {
    const std::vector<int> ids = points_of(target);
    theirs.insert(theirs.end(), ids.begin(), ids.end());
  }
  std::sort(theirs.begin(), theirs.end());
  theirs.erase(std::unique(theirs.begin(), theirs.end()), theirs.end());
  fuse(keyframe, theirs);

  // Of the keyframe's points, only those that gained observations changed.
  std::vector<bool> changed(size_t(map_.num_point_ids()), false);
  for (int id : gained) changed[size_t(id)] = true;
  for (int id : points_of(keyframe))
    if (changed[size_t(id)]) {
      map_.update_point_descriptor(id);
      map_.update_point_geometry(id);
    }
  map_.update_connections(keyframe);
  for (int target : targets) map_.update_connections(target);
  return int(gained.size());
}

double quasi_static_motion(const std::vector<Eigen::Isometry3d>& poses, double rotation_weight) {
  double s = 0;
  for (size_t i = 1; i < poses.size(); ++i) {
    const Eigen::Isometry3d step = poses[i - 1].inverse() * poses[i];
    const Eigen::AngleAxisd angle_axis(step.rotation());
    s += step.translation().squaredNorm() +
         rotation_weight * (angle_axis.angle() * angle_axis.axis()).squaredNorm();
  }
  return s;
}

}  // namespace slamkit
