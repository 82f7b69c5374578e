#pragma once
// The map: keyframes and the landmarks they observe. Points are created from depth when a
// keyframe is inserted (SPEC section 4: landmarks come from depth).
#include <vector>

#include "core/camera.h"
#include "map/keyframe.h"
#include "map/map_point.h"

namespace slamkit {

class Map {
 public:
  // Adds the keyframe; each keypoint with valid depth that observes no existing point
  // (point_ids[i] == -1) makes a new point, back-projected with the keyframe's pose.
  // Existing observed points count one more observation. Returns the keyframe's index.
  size_t insert_keyframe(Keyframe keyframe, const Camera& camera);

  const std::vector<Keyframe>& keyframes() const { return keyframes_; }
  const std::vector<MapPoint>& points() const { return points_; }
  const MapPoint& point(int id) const { return points_[size_t(id)]; }

  // Ids of the points observed by the last `count` keyframes, each once, ascending.
  std::vector<int> local_point_ids(size_t count) const;

 private:
  std::vector<Keyframe> keyframes_;
  std::vector<MapPoint> points_;
};

}  // namespace slamkit
