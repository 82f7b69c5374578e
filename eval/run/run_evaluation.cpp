#include "eval/run/run_evaluation.h"

#include <cstdio>
#include <string>

#include "eval/evaluation_run.h"
#include "eval/loop_accuracy.h"
#include "eval/metrics/metrics_json.h"
#include "eval/run/map_evaluation.h"
#include "io/path_kind.h"

namespace slamkit::eval {
namespace {

// printf's "%.Nf", for a line built before it is printed.
std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace

void evaluate_run_folder(const TumSequence& seq, const std::filesystem::path& out, bool plot,
                         bool quiet, const FigureFiles& figures) {
  if (!seq.groundtruth()) {
    if (!quiet) std::printf("evaluation  skipped: the sequence has no groundtruth.txt\n");
    return;
  }
  EvaluationRequest request;
  request.gt = (seq.folder() / "groundtruth.txt").string();
  request.est = (out / "trajectory.txt").string();
  request.out_dir = out.string();
  request.system_name = "slamkit";
  request.title = seq.folder().filename().string();
  request.no_plot = !plot;
  request.figures = figures;
  request.quiet = quiet;
  if (seq.duration() < 2.0) {  // too short for the benchmark's 1 s drift: consecutive frames
    request.unit = "f";
    request.rpe.delta = 1;
  }
  // Plots were not asked for with --plot, so a plot that cannot be drawn is a note, not a failure.
  run_evaluation(request, true, true);
}

void evaluate_run_loops(const TumSequence& seq, const std::filesystem::path& out, bool quiet) {
  if (!seq.groundtruth()) return;
  const std::filesystem::path revisits = seq.folder() / "revisits.txt";
  std::optional<std::vector<RevisitEpisode>> episodes;
  if (path_kind(revisits) == PathKind::kFile) episodes = read_revisit_episodes(revisits);
  const LoopAccuracy a =
      judge_loops(read_accepted_loops(out / "loops.csv"), *seq.groundtruth(), episodes);
  std::string line = "loop check  " + std::to_string(a.accepted) + " accepted: " +
                     std::to_string(a.true_loops) + " true, " + std::to_string(a.false_loops()) +
                     " false";
  if (a.unjudged > 0) line += ", " + std::to_string(a.unjudged) + " without groundtruth";
  nlohmann::json update = {{"loops_accepted", a.accepted}, {"loops_false", a.false_loops()}};
  if (const auto precision = a.precision()) {
    line += " (precision " + fixed(*precision, 2) + ")";
    update["loop_precision"] = *precision;
  }
  const LoopCriteria criteria;
  if (a.accepted > 0)
    line += ", " + std::to_string(a.same_place) + " within " + fixed(criteria.max_distance_m, 1) +
            " m and " + fixed(criteria.max_angle_deg, 0) + " deg";
  if (a.episodes && *a.episodes > 0)
    line += "; " + std::to_string(a.episodes_found) + " of " + std::to_string(*a.episodes) +
            " revisits found";
  if (const auto recall = a.recall()) {
    line += " (recall " + fixed(*recall, 2) + ")";
    update["loop_recall"] = *recall;
  }
  if (!quiet) std::printf("%s\n", line.c_str());
  merge_into_metrics_file(out / "metrics.json", update);
  write_loop_check_csv(out / "loop_check.csv", a);
}

void evaluate_run_map(const TumSequence& seq, double max_depth, const std::filesystem::path& out,
                      bool quiet) {
  synth::MapQualitySettings quality_settings;
  quality_settings.max_depth = max_depth;
  const std::optional<synth::MapQuality> quality =
      evaluate_map(out / "map.ply", seq.folder(), out / "trajectory.txt", quality_settings);
  if (!quality) return;
  if (!quiet) print_map_quality(*quality);
  nlohmann::json update;
  synth::add_map_quality_json(update, *quality);
  merge_into_metrics_file(out / "metrics.json", update);
}

}  // namespace slamkit::eval
