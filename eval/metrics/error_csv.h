#pragma once
// Per-pose and per-pair error tables (CSV with a header), for plots and other tools.
#include <filesystem>

#include "eval/metrics/ate.h"
#include "eval/metrics/rpe.h"

namespace slamkit::eval {

// errors.csv: time,ate_m,est_tx,est_ty,est_tz,gt_tx,gt_ty,gt_tz,rot_deg
// (estimate time; aligned estimated and groundtruth positions in metres).
void write_ate_csv(const std::filesystem::path& path, const AteResult& ate);

// rpe.csv: time_i,time_j,gt_time_i,gt_time_j,trans_m,rot_deg (as evaluate_rpe.py --save).
void write_rpe_csv(const std::filesystem::path& path, const RpeResult& rpe);

}  // namespace slamkit::eval
