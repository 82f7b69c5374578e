#pragma once
// A landmark: a 3D point, the keyframe keypoints that observe it, and what projection search
// needs to find it again (as ORB-SLAM2's map points keep it;
// docs/method.md#local-mapping-and-bundle-adjustment).
#include <Eigen/Core>
#include <vector>

#include "features/descriptor.h"

namespace slamkit {

struct Observation {
  int keyframe = -1;  // index into Map::keyframes()
  int keypoint = -1;  // index into that keyframe's keypoints
};

struct MapPoint {
  Eigen::Vector3d p_w = Eigen::Vector3d::Zero();  // world position, metres
  // The observation descriptor with the least median Hamming distance to the others.
  // Held by value: a cv::Mat took 96 bytes in the point and about 100 more on the heap.
  Descriptor descriptor{};
  std::vector<Observation> observations;  // one per keyframe, in insertion order
  int reference_keyframe = -1;            // the keyframe that created it
  int octave = 0;                         // of its keypoint in the reference keyframe
  // Mean unit direction from the observing cameras to the point, and the distance range
  // within which the pyramid can detect it (ORB-SLAM2's UpdateNormalAndDepth).
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  double min_distance = 0, max_distance = 0;
  // Tracking counters for culling: frames whose view contained the point, frames that
  // matched it as an inlier (both start at 1, as ORB-SLAM2's).
  int visible = 1, found = 1;
  bool bad = false;  // culled or merged away (Map::point then returns an empty one); ids stay

  int num_observations() const { return static_cast<int>(observations.size()); }
  double found_ratio() const { return double(found) / double(visible); }
};

}  // namespace slamkit
