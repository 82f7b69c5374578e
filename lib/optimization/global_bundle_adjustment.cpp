#include "optimization/ba_solver.h"
#include "optimization/bundle_adjustment.h"

namespace slamkit {

BaReport global_bundle_adjustment(BaProblem& problem, const BaIntrinsics& intrinsics,
                                  const BaResidualSettings& residual,
                                  const GlobalBaSettings& settings) {
  // ORB-SLAM2's global BA is plain least squares over every observation; robust adds the
  // local BA's Huber stage and outlier pass.
  return solve_with_schedule(problem, intrinsics, residual, [&](BaSolver& solver) {
    if (!solver.run(settings.iterations, settings.robust, true)) return false;
    if (!settings.robust) return true;
    solver.classify();
    return solver.run(settings.refine_iterations, false, true);
  });
}

}  // namespace slamkit
