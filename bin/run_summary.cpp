#include "bin/run_summary.h"

#include <cstdio>

#include "bin/eval_run.h"
#include "eval/loop_accuracy.h"
#include "eval/metrics_json.h"
#include "io/path_kind.h"
#include "pipeline/run_output.h"

namespace slamkit::cli {

void print_tracking_summary(const TumSequence& seq, const RunResult& result) {
  int lost = 0, keyframes = 0, svd = 0, dense = 0;
  for (const TrackedFrame& f : result.frames) {
    lost += f.lost;
    keyframes += f.keyframe;
    svd += f.solver == PoseSolver::kSvdRansac && !f.lost;
    dense += f.solver == PoseSolver::kPointToPlane && !f.lost;
  }
  const TimingSummary timing = summarise_timing(result);
  std::printf("tracked     %zu frames of %s: %d keyframes, %d lost\n", result.frames.size(),
              seq.folder().filename().string().c_str(), keyframes, lost);
  std::printf("solvers     svd_ransac %d, point_to_plane %d, motion_model %d\n", svd, dense, lost);
  for (const std::string& line : describe_failures(result))
    std::printf("failure     %s\n", line.c_str());
  std::printf("speed       %.1f frames/s with %d threads; tracking median %.1f ms/frame\n",
              timing.frames_per_second, result.threads, timing.tracking_median_ms);
}

void evaluate_run_folder(const TumSequence& seq, const std::filesystem::path& out, bool plot) {
  if (!seq.groundtruth()) {
    std::printf("evaluation  skipped: the sequence has no groundtruth.txt\n");
    return;
  }
  EvalArgs eval_args;
  eval_args.gt = (seq.folder() / "groundtruth.txt").string();
  eval_args.est = (out / "trajectory.txt").string();
  eval_args.out_dir = out.string();
  eval_args.system_name = "slamkit";
  eval_args.title = seq.folder().filename().string();
  eval_args.no_plot = !plot;
  if (seq.duration() < 2.0) {  // too short for the benchmark's 1 s drift: consecutive frames
    eval_args.unit = "f";
    eval_args.rpe.delta = 1;
  }
  run_eval(eval_args, true, true);
}

void evaluate_run_loops(const TumSequence& seq, const std::filesystem::path& out) {
  if (!seq.groundtruth()) return;
  const std::filesystem::path revisits = seq.folder() / "revisits.txt";
  std::optional<std::vector<eval::RevisitEpisode>> episodes;
  if (path_kind(revisits) == PathKind::kFile) episodes = eval::read_revisit_episodes(revisits);
  const eval::LoopAccuracy a =
      eval::judge_loops(eval::read_accepted_loops(out / "loops.csv"), *seq.groundtruth(), episodes);
  std::printf("loop check  %d accepted: %d true, %d false", a.accepted, a.true_loops,
              a.false_loops());
  if (a.unjudged > 0) std::printf(", %d without groundtruth", a.unjudged);
  nlohmann::json update = {{"loops_accepted", a.accepted}, {"loops_false", a.false_loops()}};
  if (const auto precision = a.precision()) {
    std::printf(" (precision %.2f)", *precision);
    update["loop_precision"] = *precision;
  }
  const eval::LoopCriteria criteria;
  if (a.accepted > 0)
    std::printf(", %d within %.1f m and %.0f deg", a.same_place, criteria.max_distance_m,
                criteria.max_angle_deg);
  if (a.episodes && *a.episodes > 0)
    std::printf("; %d of %d revisits found", a.episodes_found, *a.episodes);
  if (const auto recall = a.recall()) {
    std::printf(" (recall %.2f)", *recall);
    update["loop_recall"] = *recall;
  }
  std::printf("\n");
  eval::merge_into_metrics_file(out / "metrics.json", update);
}

void StageProgress::operator()(const std::string& stage, size_t done, size_t total) {
  std::unique_ptr<Progress>& bar = bars_[stage];
  if (!bar) bar = std::make_unique<Progress>(stage, total);
  bar->update(done);
}

}  // namespace slamkit::cli
