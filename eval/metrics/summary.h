#pragma once
// The human summary printed by `slamkit eval`, in the style of the benchmark scripts'
// --verbose output (one "name value unit" per line).
#include <string>

#include "eval/metrics/ate.h"
#include "eval/metrics/coverage.h"
#include "eval/metrics/kitti_odometry.h"
#include "eval/metrics/rpe.h"

namespace slamkit::eval {

std::string ate_summary(const AteResult& ate, const Coverage& coverage);
std::string rpe_summary(const RpeResult& rpe, const RpeOptions& options);
std::string kitti_summary(const KittiOdometryResult& kitti, size_t pairs);

}  // namespace slamkit::eval
