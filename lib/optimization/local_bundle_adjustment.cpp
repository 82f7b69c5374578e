#include "optimization/ba_solver.h"
#include "optimization/bundle_adjustment.h"

namespace slamkit {

BaReport local_bundle_adjustment(BaProblem& problem, const BaIntrinsics& intrinsics,
                                 const BaResidualSettings& residual,
                                 const LocalBaSettings& settings) {
  // The points move during the first fix_points_after_iterations iterations of the whole
  // schedule, counted over both stages; after that only the poses do.
  const int fix_after = settings.fix_points_after_iterations;
  return solve_with_schedule(problem, intrinsics, residual, [&](BaSolver& solver) {
    // ORB-SLAM2: Huber, then the observations failing the chi-square test (or behind the
    // camera) are left out and the rest refined without the kernel.
    if (!solver.run_stage(0, settings.robust_iterations, true, fix_after)) return false;
    solver.classify();
    return solver.run_stage(settings.robust_iterations, settings.refine_iterations, false,
                            fix_after);
  });
}

}  // namespace slamkit
