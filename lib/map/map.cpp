#include "map/map.h"

#include <algorithm>
#include <limits>

namespace slamkit {

size_t Map::insert_keyframe(Keyframe keyframe, const Camera& camera) {
  const size_t index = keyframes_.size();
  keyframe.T_c_w = keyframe.T_w_c.inverse();
  for (size_t i = 0; i < keyframe.keypoints.size(); ++i) {
    int& id = keyframe.point_ids[i];
    if (id >= 0) {
      ++points_[size_t(id)].observations;
      continue;
    }
    if (keyframe.depths[i] <= 0) continue;
    MapPoint point;
    point.p_w = keyframe.T_w_c * camera.back_project(keyframe.undistorted[i], keyframe.depths[i]);
    point.descriptor = keyframe.descriptors.row(int(i)).clone();
    point.octave = keyframe.keypoints[i].octave;
    point.first_keyframe = index;
    id = int(points_.size());
    points_.push_back(std::move(point));
  }
  keyframes_.push_back(std::move(keyframe));
  return index;
}

std::vector<int> Map::local_point_ids(size_t count) const {
  // Recent keyframes see recent points, so the ids span a short range: marking them there and
  // reading the marks in order is cheaper than sorting the ids and removing repeats.
  const size_t first = keyframes_.size() > count ? keyframes_.size() - count : 0;
  int lowest = std::numeric_limits<int>::max(), highest = -1;
  for (size_t k = first; k < keyframes_.size(); ++k)
    for (int id : keyframes_[k].point_ids)
      if (id >= 0) lowest = std::min(lowest, id), highest = std::max(highest, id);
  std::vector<int> ids;
  if (highest < 0) return ids;
  std::vector<bool> seen(size_t(highest - lowest + 1), false);
  for (size_t k = first; k < keyframes_.size(); ++k)
    for (int id : keyframes_[k].point_ids)
      if (id >= 0) seen[size_t(id - lowest)] = true;
  for (size_t i = 0; i < seen.size(); ++i)
    if (seen[i]) ids.push_back(lowest + int(i));
  return ids;
}

}  // namespace slamkit
