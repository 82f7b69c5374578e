#include "tracking/tracked_frame.h"

#include "core/enum_names.h"

namespace slamkit {

const char* solver_name(PoseSolver solver) {
  static constexpr EnumNames<PoseSolver, 4> kNames = {
      {{PoseSolver::kFirstFrame, "first"},
       {PoseSolver::kSvdRansac, "svd_ransac"},
       {PoseSolver::kPointToPlane, "point_to_plane"},
       {PoseSolver::kMotionModel, "motion_model"}}};
  return name_of(kNames, solver);
}

}  // namespace slamkit
