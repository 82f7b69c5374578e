#pragma once
// The map as data (stella_vslam's data/ layer): keyframes, map points with their observations,
// the covisibility graph and the spanning tree, kept consistent with each other. What happens
// to the map at a new keyframe (new points, culling, duplicate fusion, local BA) lives in
// lib/mapping; the problems built from it in lib/optimization.
#include <memory>
#include <vector>

#include "core/camera.h"
#include "map/keyframe.h"
#include "map/map_point.h"

namespace slamkit {

// What the map needs of the feature pyramid to give a point its scale-valid distance range.
struct PyramidGeometry {
  int levels = 4;
  double scale_factor = 1.2;
  double scale(int octave) const;
};

class Map {
 public:
  explicit Map(PyramidGeometry pyramid = {}, int covisibility_min_shared = 15)
      : pyramid_(pyramid), covisibility_min_shared_(covisibility_min_shared) {}
  // Copies are deep (a test runs the loop pass on a copy of a mapped run's map).
  Map(const Map& other);
  Map& operator=(const Map& other);
  Map(Map&&) noexcept = default;
  Map& operator=(Map&&) noexcept = default;

  // Adds the keyframe as it is (its point_ids must be -1 or valid points it observes: those
  // observations are added). Returns its index. The caller then makes new points
  // (add_point) and calls update_connections.
  int add_keyframe(Keyframe keyframe);
  // A new point observed by keypoint `keypoint` of `keyframe`, which becomes its reference.
  int add_point(const Eigen::Vector3d& p_w, int keyframe, int keypoint);

  void add_observation(int point, int keyframe, int keypoint);
  // Removes the point from the keyframe (and the keyframe's link to it); a point left with
  // no observation is marked bad.
  void erase_observation(int point, int keyframe);
  // Marks the point bad and removes every observation of it.
  void cull_point(int point);
  // Merges `duplicate` into `survivor`: its observations move over (unless the survivor is
  // already seen by that keyframe), its counters add, and it is marked bad.
  void replace_point(int duplicate, int survivor);

  // Removes a redundant keyframe (ORB-SLAM2's SetBadFlag): its observations and covisibility
  // links go, and each child takes as parent the most covisible of the culled keyframe's parent
  // and the children re-parented so far, among those older than it (parents stay older than
  // their children); a child linked to none of them takes the culled keyframe's parent. The
  // culled keyframe keeps its index and its parent, at its present relative pose.
  void cull_keyframe(int keyframe);
  // Puts every culled keyframe at its parent's pose times T_parent_c, oldest first (after
  // its parent moved, e.g. in global BA).
  void place_culled_keyframes();
  int num_culled_keyframes() const;
  // The keyframes not culled: those the loop pass, global BA and the fused map use.
  int num_active_keyframes() const { return int(keyframes_.size()) - num_culled_keyframes(); }

  // Recounts the points the keyframe shares with every other keyframe, links them in the
  // covisibility graph (both ways) and, the first time, sets its parent in the spanning tree.
  void update_connections(int keyframe);
  // The representative descriptor (among the last kDescriptorViews observations), mean
  // viewing direction and distance range of a point, from its current observations.
  static constexpr size_t kDescriptorViews = 32;
  void update_point_descriptor(int point);
  void update_point_geometry(int point);

  // Up to `count` covisible neighbours, best first (count <= 0: all).
  std::vector<int> best_covisible(int keyframe, int count) const;
  // The octave at which a point at `distance` should be detected (ORB-SLAM2's PredictScale).
  int predict_octave(const MapPoint& point, double distance) const;

  void set_keyframe_pose(int keyframe, const Eigen::Isometry3d& T_w_c);
  // New pinhole pixels and depths for the keyframe's keypoints (same count and order).
  void set_keyframe_keypoints(int keyframe, std::vector<Eigen::Vector2d> undistorted,
                              std::vector<float> depths);
  // No effect on a point culled or merged away (a BA result may arrive after that).
  void set_point_position(int point, const Eigen::Vector3d& p_w);
  void count_visible(int point);
  void count_found(int point);

  const std::vector<Keyframe>& keyframes() const { return keyframes_; }
  const Keyframe& keyframe(int id) const { return keyframes_[size_t(id)]; }
  // Every id ever given out stays valid. A point culled or merged away gives its storage back
  // (on a long sequence most ids are such points); point() then returns an empty point
  // marked bad.
  int num_point_ids() const { return int(points_.size()); }
  const MapPoint& point(int id) const;
  const PyramidGeometry& pyramid() const { return pyramid_; }
  int num_good_points() const;

 private:
  MapPoint& live(int id);  // throws std::logic_error for a point culled or merged away
  void release(int id);
  void link(int keyframe, int other, int weight);
  void sort_covisible(int keyframe);

  PyramidGeometry pyramid_;
  int covisibility_min_shared_;
  std::vector<Keyframe> keyframes_;
  std::vector<std::unique_ptr<MapPoint>> points_;
};

}  // namespace slamkit
