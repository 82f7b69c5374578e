#include <algorithm>
#include <limits>

#include "optimization/ba_solver.h"
#include "optimization/bundle_adjustment.h"

namespace slamkit {

BaReport local_bundle_adjustment(BaProblem& problem, const BaIntrinsics& intrinsics,
                                 const BaResidualSettings& residual,
                                 const LocalBaSettings& settings) {
  // The points move during the first fix_points_after_iterations iterations of the whole
  // schedule, counted over both stages; after that only the poses do.
  const int fix_points_after = settings.fix_points_after_iterations < 0
                                   ? std::numeric_limits<int>::max()
                                   : settings.fix_points_after_iterations;
  return solve_with_schedule(problem, intrinsics, residual, [&](BaSolver& solver) {
    // `iterations` LM iterations starting at schedule iteration `first`, split where the
    // points become fixed.
    const auto run_stage = [&](int first, int iterations, bool robust) {
      const int with_points = std::clamp(fix_points_after - first, 0, iterations);
      return solver.run(with_points, robust, true) &&
             solver.run(iterations - with_points, robust, false);
    };
    // ORB-SLAM2: Huber, then the observations failing the chi-square test (or behind the
    // camera) are left out and the rest refined without the kernel.
    if (!run_stage(0, settings.robust_iterations, true)) return false;
    solver.classify();
    return run_stage(settings.robust_iterations, settings.refine_iterations, false);
  });
}

}  // namespace slamkit
