#pragma once
// What happens to the map at each new keyframe (stella_vslam's mapping_module, ORB-SLAM2's
// LocalMapping; docs/method.md#local-mapping-and-bundle-adjustment): the tracked points gain
// the keyframe's observations, keypoints with depth and no point make new points, the
// covisibility graph is updated, recent points on probation are culled, duplicates in the
// neighbourhood are fused, and local BA adjusts the window.
#include <future>
#include <memory>
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
  int culled_keyframes = 0;  // redundant neighbours culled after this keyframe's local BA
  bool ba_run = false;       // false: disabled, too few keyframes, or the camera was quasi-static
  MapAdjustment ba;          // when ba_run
  double ms = 0;          // the insertion on the tracking thread, waiting for the last BA included
  double ba_wait_ms = 0;  // of which waiting for the previous keyframe's BA to finish
};

class LocalMapper {
 public:
  // concurrent: local BA on its own thread (else at the point where it is applied).
  LocalMapper(const Camera& camera, const Settings& settings, Map& map, bool concurrent);

  // Inserts the keyframe (its point_ids hold the points tracking matched) and maintains the
  // map. `motion` is the paper's s_e over the frames since the previous keyframe. Local BA
  // runs beside tracking when concurrent (as ORB-SLAM2's local mapping thread does) and is
  // applied at a fixed point in the frame order: the next keyframe's insertion, or finish().
  // So the map tracking sees, and every result, is the same whether it ran beside or not.
  // Returns the keyframe's index in the map.
  int insert_keyframe(Keyframe keyframe, double motion);

  // Waits for a local BA still running and applies it.
  void finish();

  // One per keyframe inserted; a keyframe's BA numbers are filled in when it is applied.
  const std::vector<MappingReport>& reports() const { return reports_; }

 private:
  int create_points(int keyframe);
  int cull_recent_points(int keyframe);
  int fuse_duplicates(int keyframe);
  int cull_redundant_keyframes(int keyframe);
  bool redundant(int keyframe) const;

  Camera camera_;
  Settings settings_;
  Map& map_;
  std::vector<int> recent_points_;  // ORB-SLAM2's probation list
  std::vector<MappingReport> reports_;
  std::launch launch_;
  std::unique_ptr<MapBaJob> pending_;  // the last keyframe's local BA, not yet applied
  std::future<void> solving_;
  int cull_around_ = -1;  // the keyframe whose neighbours are checked once its BA is applied
};

// The paper's quasi-static measure over consecutive poses: s_e = sum |t_i|^2 + w_e sum
// |(alpha, beta, gamma)_i|^2 of the relative motions (small-angle rotation vector).
double quasi_static_motion(const std::vector<Eigen::Isometry3d>& poses, double rotation_weight);

}  // namespace slamkit
