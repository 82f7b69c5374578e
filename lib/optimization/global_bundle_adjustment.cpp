#include "optimization/ba_solver.h"
#include "optimization/bundle_adjustment.h"

namespace slamkit {

BaReport global_bundle_adjustment(BaProblem& problem, const BaIntrinsics& intrinsics,
                                  const BaResidualSettings& residual,
                                  const GlobalBaSettings& settings) {
  // ORB-SLAM2's global BA is plain least squares over every observation; robust adds the
  // local BA's Huber stage and outlier pass. The points are held as local BA holds them.
  const int fix_after = settings.fix_points_after_iterations;
  return solve_with_schedule(problem, intrinsics, residual, [&](BaSolver& solver) {
    if (!solver.run_stage(0, settings.iterations, settings.robust, fix_after)) return false;
    if (!settings.robust) return true;
    solver.classify();
    return solver.run_stage(settings.iterations, settings.refine_iterations, false, fix_after);
  });
}

}  // namespace slamkit
