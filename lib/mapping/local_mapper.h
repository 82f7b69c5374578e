#pragma once
// What happens to the map at each new keyframe (stella_vslam's mapping_module, ORB-SLAM2's
// LocalMapping, ORBSLAM2_BACKEND.md section 1): the tracked points gain the keyframe's
// observations, keypoints with depth and no point make new points, the covisibility graph is
// updated, recent points on probation are culled, duplicates in the neighbourhood are fused,
// and local BA adjusts the window (SPEC section 4).
#include <vector>

#include "core/camera.h"
#include "core/settings/settings.h"
#include "map/map.h"
#include "optimization/map_adjustment.h"

namespace slamkit {

struct MappingReport {
  int keyframe = -1;
  int new_points = 0;
  int culled_points = 0;
  int fused_points = 0;
  bool ba_run = false;    // false: disabled, too few keyframes, or the camera was quasi-static
  MapAdjustment ba;       // when ba_run
  double ms = 0;          // the whole insertion, BA included
};

class LocalMapper {
 public:
  LocalMapper(const Camera& camera, const Settings& settings, Map& map);

  // Inserts the keyframe (its point_ids hold the points tracking matched) and maintains the
  // map. `motion` is the paper's s_e over the frames since the previous keyframe.
  MappingReport insert_keyframe(Keyframe keyframe, double motion);

 private:
  int create_points(int keyframe);
  int cull_recent_points(int keyframe);
  int fuse_duplicates(int keyframe);

  Camera camera_;
  Settings settings_;
  Map& map_;
  std::vector<int> recent_points_;  // ORB-SLAM2's probation list
};

// The paper's quasi-static measure over consecutive poses: s_e = sum |t_i|^2 + w_e sum
// |(alpha, beta, gamma)_i|^2 of the relative motions (small-angle rotation vector).
double quasi_static_motion(const std::vector<Eigen::Isometry3d>& poses, double rotation_weight);

}  // namespace slamkit
