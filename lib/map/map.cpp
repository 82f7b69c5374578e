#include "map/map.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "features/descriptor.h"

namespace slamkit {

double PyramidGeometry::scale(int octave) const { return std::pow(scale_factor, octave); }

namespace {
const MapPoint kReleasedPoint = [] {
  MapPoint p;
  p.bad = true;
  return p;
}();

// The ((n - 1) / 2)-th smallest of values[0, n), each a descriptor distance (0 to 256): the
// smallest v with more than (n - 1) / 2 values at most v, found by bisection on v with
// branch-free counts. std::nth_element gave the same value, at a mispredicted branch per
// comparison (3 % of `run`'s CPU on synthetic desk 600).
int lower_median(const int* values, size_t n) {
  const size_t rank = (n - 1) / 2;
  int lo = 0, hi = kDescriptorBytes * 8;  // the value sought is in [lo, hi]
  while (lo < hi) {
    const int mid = (lo + hi) / 2;
    size_t at_most = 0;
    for (size_t j = 0; j < n; ++j) at_most += values[j] <= mid;
    if (at_most > rank)
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

}  // namespace

Map::Map(const Map& other)
    : pyramid_(other.pyramid_),
      covisibility_min_shared_(other.covisibility_min_shared_),
      keyframes_(other.keyframes_) {
  points_.reserve(other.points_.size());
  for (const std::unique_ptr<MapPoint>& p : other.points_)
    points_.push_back(p ? std::make_unique<MapPoint>(*p) : nullptr);
}

Map& Map::operator=(const Map& other) {
  if (this != &other) *this = Map(other);
  return *this;
}

const MapPoint& Map::point(int id) const {
  const std::unique_ptr<MapPoint>& p = points_[size_t(id)];
  return p ? *p : kReleasedPoint;
}

MapPoint& Map::live(int id) {
  if (!points_[size_t(id)])
    throw std::logic_error("map point " + std::to_string(id) + " was culled or merged away");
  return *points_[size_t(id)];
}

void Map::release(int id) { points_[size_t(id)].reset(); }

void Map::set_point_position(int point, const Eigen::Vector3d& p_w) {
  if (points_[size_t(point)]) points_[size_t(point)]->p_w = p_w;
}
void Map::count_visible(int point) {
  if (points_[size_t(point)]) ++points_[size_t(point)]->visible;
}
void Map::count_found(int point) {
  if (points_[size_t(point)]) ++points_[size_t(point)]->found;
}

int Map::add_keyframe(Keyframe keyframe) {
  const int id = static_cast<int>(keyframes_.size());
  keyframe.set_pose(keyframe.T_w_c);
  keyframes_.push_back(std::move(keyframe));
  Keyframe& k = keyframes_.back();
  for (size_t i = 0; i < k.point_ids.size(); ++i) {
    const int point = k.point_ids[i];
    if (point < 0) continue;
    k.point_ids[i] = -1;  // add_observation links it again, unless the point is gone
    if (!this->point(point).bad) add_observation(point, id, static_cast<int>(i));
  }
  return id;
}

int Map::add_point(const Eigen::Vector3d& p_w, int keyframe, int keypoint) {
  const int id = static_cast<int>(points_.size());
  MapPoint point;
  point.p_w = p_w;
  point.reference_keyframe = keyframe;
  point.octave = keyframes_[size_t(keyframe)].keypoints[size_t(keypoint)].octave;
  points_.push_back(std::make_unique<MapPoint>(std::move(point)));
  add_observation(id, keyframe, keypoint);
  update_point_descriptor(id);
  update_point_geometry(id);
  return id;
}

void Map::add_observation(int point, int keyframe, int keypoint) {
  MapPoint& p = live(point);
  for (const Observation& o : p.observations)
    if (o.keyframe == keyframe) return;  // one observation per keyframe
  int& link = keyframes_[size_t(keyframe)].point_ids[size_t(keypoint)];
  if (link >= 0 && link != point) erase_observation(link, keyframe);
  link = point;
  p.observations.push_back({keyframe, keypoint});
}

void Map::erase_observation(int point, int keyframe) {
  if (!points_[size_t(point)]) return;  // culled: nothing left to erase
  MapPoint& p = *points_[size_t(point)];
  const auto it = std::find_if(p.observations.begin(), p.observations.end(),
                               [&](const Observation& o) { return o.keyframe == keyframe; });
  if (it == p.observations.end()) return;
  keyframes_[size_t(keyframe)].point_ids[size_t(it->keypoint)] = -1;
  p.observations.erase(it);
  if (p.observations.empty()) {
    release(point);
    return;
  }
  if (p.reference_keyframe == keyframe) {
    const Observation& first = p.observations.front();
    p.reference_keyframe = first.keyframe;
    p.octave = keyframes_[size_t(first.keyframe)].keypoints[size_t(first.keypoint)].octave;
  }
}

void Map::cull_point(int point) {
  if (!points_[size_t(point)]) return;
  for (const Observation& o : points_[size_t(point)]->observations)
    keyframes_[size_t(o.keyframe)].point_ids[size_t(o.keypoint)] = -1;
  release(point);
}

void Map::replace_point(int duplicate, int survivor) {
  if (duplicate == survivor || !points_[size_t(duplicate)]) return;
  MapPoint& dup = *points_[size_t(duplicate)];
  MapPoint& kept = live(survivor);
  for (const Observation& o : dup.observations) {
    int& link = keyframes_[size_t(o.keyframe)].point_ids[size_t(o.keypoint)];
    const bool seen = std::any_of(kept.observations.begin(), kept.observations.end(),
                                  [&](const Observation& k) { return k.keyframe == o.keyframe; });
    if (seen) {
      link = -1;
    } else {
      link = survivor;
      kept.observations.push_back(o);
    }
  }
  kept.visible += dup.visible;
  kept.found += dup.found;
  release(duplicate);
  update_point_descriptor(survivor);
}

void Map::update_connections(int keyframe) {
  Keyframe& k = keyframes_[size_t(keyframe)];
  // Counted in one slot a keyframe: a tree map's look-up per observation cost more.
  std::vector<int> count(keyframes_.size(), 0);
  for (int point : k.point_ids) {
    if (point < 0) continue;
    for (const Observation& o : this->point(point).observations)
      if (o.keyframe != keyframe) ++count[size_t(o.keyframe)];
  }
  std::map<int, int> shared;
  for (size_t other = 0; other < count.size(); ++other)
    if (count[other] > 0) shared.emplace_hint(shared.end(), int(other), count[other]);
  // Keyframes that no longer share anything drop their side of the link.
  for (const auto& [other, weight] : k.shared_points)
    if (!shared.count(other)) {
      keyframes_[size_t(other)].shared_points.erase(keyframe);
      sort_covisible(other);
    }
  k.shared_points = shared;
  for (const auto& [other, weight] : shared) link(other, keyframe, weight);
  sort_covisible(keyframe);

  if (k.parent < 0 && keyframe > 0) {
    // The spanning tree takes the best neighbour once; a keyframe sharing nothing (after a
    // tracking failure) hangs from the previous one so that the tree stays connected.
    k.parent = k.covisible.empty() ? keyframe - 1 : k.covisible.front();
    keyframes_[size_t(k.parent)].children.push_back(keyframe);
  }
}

void Map::cull_keyframe(int keyframe) {
  Keyframe& k = keyframes_[size_t(keyframe)];
  if (k.culled || k.parent < 0) return;  // the first keyframe holds the world frame
  for (int point : std::vector<int>(k.point_ids))
    if (point >= 0) erase_observation(point, keyframe);
  for (const auto& [other, weight] : k.shared_points) {
    keyframes_[size_t(other)].shared_points.erase(keyframe);
    sort_covisible(other);
  }
  k.shared_points.clear();
  k.covisible.clear();

  // ORB-SLAM2's re-parenting: repeatedly the (child, candidate) pair of largest covisibility
  // weight, the child then becoming a candidate too.
  std::vector<int> candidates = {k.parent};
  std::vector<int> orphans = k.children;
  while (!orphans.empty()) {
    int best_child = -1, best_parent = -1, best_weight = -1;
    for (int child : orphans)
      for (int candidate : candidates) {
        const auto& shared = keyframes_[size_t(child)].shared_points;
        const auto it = shared.find(candidate);
        if (candidate < child && it != shared.end() && it->second > best_weight)
          best_child = child, best_parent = candidate, best_weight = it->second;
      }
    if (best_child < 0) break;
    keyframes_[size_t(best_child)].parent = best_parent;
    keyframes_[size_t(best_parent)].children.push_back(best_child);
    candidates.push_back(best_child);
    orphans.erase(std::find(orphans.begin(), orphans.end(), best_child));
  }
  for (int child : orphans) {
    keyframes_[size_t(child)].parent = k.parent;
    keyframes_[size_t(k.parent)].children.push_back(child);
  }
  k.children.clear();
  std::vector<int>& siblings = keyframes_[size_t(k.parent)].children;
  siblings.erase(std::remove(siblings.begin(), siblings.end(), keyframe), siblings.end());
  k.T_parent_c = keyframes_[size_t(k.parent)].T_c_w * k.T_w_c;
  k.culled = true;
}

void Map::place_culled_keyframes() {
  for (Keyframe& k : keyframes_)  // a parent is older than its child: placed first
    if (k.culled) k.set_pose(keyframes_[size_t(k.parent)].T_w_c * k.T_parent_c);
}

int Map::num_culled_keyframes() const {
  return int(std::count_if(keyframes_.begin(), keyframes_.end(),
                           [](const Keyframe& k) { return k.culled; }));
}

void Map::link(int keyframe, int other, int weight) {
  // Moves `other` within the sorted neighbour list instead of sorting it again: in a room every
  // keyframe neighbours hundreds of others, and each new keyframe updates all of them.
  Keyframe& k = keyframes_[size_t(keyframe)];
  std::vector<int>& list = k.covisible;
  const auto weight_of = [&](int n) { return k.shared_points.at(n); };
  const bool fallback = list.size() == 1 && weight_of(list.front()) < covisibility_min_shared_;
  // Best first, then lowest index.
  const auto position = [&](int w, int id) {
    return std::lower_bound(list.begin(), list.end(), id, [&](int n, int) {
      const int wn = weight_of(n);
      return wn > w || (wn == w && n < id);
    });
  };
  const auto old = k.shared_points.find(other);
  if (!fallback && old != k.shared_points.end() && old->second >= covisibility_min_shared_) {
    const auto it = position(old->second, other);
    if (it != list.end() && *it == other) list.erase(it);
  }
  k.shared_points[other] = weight;
  if (fallback || list.empty()) {
    sort_covisible(keyframe);
  } else if (weight >= covisibility_min_shared_) {
    list.insert(position(weight, other), other);
  }
}

void Map::sort_covisible(int keyframe) {
  Keyframe& k = keyframes_[size_t(keyframe)];
  std::vector<std::pair<int, int>> ranked;  // (-weight, keyframe): best first, then lowest id
  for (const auto& [other, weight] : k.shared_points) ranked.push_back({-weight, other});
  std::sort(ranked.begin(), ranked.end());
  k.covisible.clear();
  for (const auto& [negative_weight, other] : ranked)
    if (-negative_weight >= covisibility_min_shared_) k.covisible.push_back(other);
  // ORB-SLAM2: with no neighbour above the threshold, the best one is linked alone.
  if (k.covisible.empty() && !ranked.empty()) k.covisible.push_back(ranked.front().second);
}

void Map::update_point_descriptor(int point) {
  if (!points_[size_t(point)]) return;
  MapPoint& p = *points_[size_t(point)];
  if (p.observations.empty()) return;
  // The choice costs the square of the views compared: over a room filmed for minutes a point
  // gathers hundreds of views (ORB-SLAM2 culls redundant keyframes; we keep them), so only the
  // most recent kDescriptorViews take part.
  const size_t first =
      p.observations.size() > kDescriptorViews ? p.observations.size() - kDescriptorViews : 0;
  const size_t n = p.observations.size() - first;
  std::vector<const uchar*> descriptors;
  for (size_t i = first; i < p.observations.size(); ++i) {
    const Observation& o = p.observations[i];
    descriptors.push_back(keyframes_[size_t(o.keyframe)].descriptors.ptr<uchar>(o.keypoint));
  }
  // The distances are symmetric: each pair is measured once.
  std::vector<int> distances(n * n, 0);
  for (size_t i = 0; i < n; ++i)
    for (size_t j = i + 1; j < n; ++j)
      distances[i * n + j] = distances[j * n + i] =
          descriptor_distance(descriptors[i], descriptors[j]);
  size_t best = 0;
  int best_median = std::numeric_limits<int>::max();
  for (size_t i = 0; i < n; ++i) {
    const int median = lower_median(distances.data() + i * n, n);
    if (median < best_median) best_median = median, best = i;
  }
  std::copy_n(descriptors[best], kDescriptorBytes, p.descriptor.begin());
}

void Map::update_point_geometry(int point) {
  if (!points_[size_t(point)]) return;
  MapPoint& p = *points_[size_t(point)];
  if (p.observations.empty()) return;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  for (const Observation& o : p.observations)
    normal += (p.p_w - keyframes_[size_t(o.keyframe)].centre()).normalized();
  p.normal = normal / double(p.observations.size());
  const Keyframe& reference = keyframes_[size_t(p.reference_keyframe)];
  const double distance = (p.p_w - reference.centre()).norm();
  p.max_distance = distance * pyramid_.scale(p.octave);
  p.min_distance = p.max_distance / pyramid_.scale(pyramid_.levels - 1);
}

std::vector<int> Map::best_covisible(int keyframe, int count) const {
  const std::vector<int>& all = keyframes_[size_t(keyframe)].covisible;
  if (count <= 0 || size_t(count) >= all.size()) return all;
  return {all.begin(), all.begin() + count};
}

int Map::predict_octave(const MapPoint& point, double distance) const {
  if (distance <= 0 || point.max_distance <= 0) return point.octave;
  const int octave = static_cast<int>(
      std::ceil(std::log(point.max_distance / distance) / std::log(pyramid_.scale_factor)));
  return std::clamp(octave, 0, pyramid_.levels - 1);
}

void Map::set_keyframe_keypoints(int keyframe, std::vector<Eigen::Vector2d> undistorted,
                                 std::vector<float> depths) {
  Keyframe& k = keyframes_[size_t(keyframe)];
  if (undistorted.size() != k.keypoints.size() || depths.size() != k.keypoints.size())
    throw std::invalid_argument("set_keyframe_keypoints: one pixel and depth per keypoint");
  k.undistorted = std::move(undistorted);
  k.depths = std::move(depths);
}

void Map::set_keyframe_pose(int keyframe, const Eigen::Isometry3d& T_w_c) {
  keyframes_[size_t(keyframe)].set_pose(T_w_c);
}

int Map::num_good_points() const {
  return static_cast<int>(
      std::count_if(points_.begin(), points_.end(), [](const auto& p) { return p != nullptr; }));
}

}  // namespace slamkit
