#include "core/stopwatch.h"
#include "optimization/ba_solver.h"
#include "optimization/bundle_adjustment.h"

namespace slamkit {

BaReport global_bundle_adjustment(BaProblem& problem, const BaIntrinsics& intrinsics,
                                  const BaResidualSettings& residual,
                                  const GlobalBaSettings& settings) {
  Stopwatch stopwatch;
  BaSolver solver(problem, intrinsics, residual);
  BaReport report;
  report.outlier.assign(problem.observations.size(), false);
  if (!solver.solvable()) return report;

  // ORB-SLAM2's global BA is plain least squares over every observation; robust adds the
  // local BA's Huber stage and outlier pass.
  bool solved = solver.run(settings.iterations, settings.robust, true);
  if (solved && settings.robust) {
    solver.classify();
    solved = solver.run(settings.refine_iterations, false, true);
  }
  if (!solved) return report;
  solver.classify();
  solver.write_back(problem);
  report = solver.report();
  report.seconds = stopwatch.lap() * 1e-3;
  return report;
}

}  // namespace slamkit
