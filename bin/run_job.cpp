#include "bin/run_job.h"

#include <algorithm>
#include <cstdio>
#include <optional>

#include "bin/report_writing.h"
#include "bin/run_summary.h"
#include "eval/run/run_evaluation.h"
#include "pipeline/run_pipeline.h"

namespace slamkit::cli {
namespace {

namespace fs = std::filesystem;

// The run's engine part: `run`'s whole batch or `track`'s front end, with its outputs written.
RunResult run_stages(const TumSequence& seq, const fs::path& out, const RunJob& job,
                     const ProgressCallback& progress) {
  const std::string name = seq.folder().filename().string();
  if (job.back_end) return run_batch(seq, job.settings, out, name, progress, job.vocabulary);
  RunResult result = track_sequence(seq, job.settings, progress);
  write_run_outputs(out, name, seq.camera(), job.settings, result);
  write_timing_json(out, name, result);
  return result;
}

// The figure files the run writes: those asked for, and the SVGs its page shows.
eval::FigureFiles figure_files(const RunJob& job) {
  eval::FigureFiles files = job.figures;
  const bool page = job.back_end && job.settings.report.enabled;
  const auto& formats = files.formats;
  if (page && !formats.empty() && std::find(formats.begin(), formats.end(), "svg") == formats.end())
    files.formats.push_back("svg");
  return files;
}

void print_outputs(const fs::path& out, const RunResult& result) {
  std::printf("output      %s\n", out.c_str());
  if (result.fusion.frames > 0) std::printf("map         %s\n", (out / "map.ply").c_str());
  if (result.fusion.triangles > 0) std::printf("mesh        %s\n", (out / "mesh.ply").c_str());
}

}  // namespace

RunResult run_into_folder(const TumSequence& seq, const fs::path& out, const RunJob& job,
                          const ProgressCallback& progress) {
  const Settings& settings = job.settings;
  RunResult result;
  fill_run_folder(begin_run_folder(out, settings, job.on_signal), [&] {
    {
      std::optional<StageProgress> bars;  // ended (their lines finished) before the summary
      if (job.progress_bars) bars.emplace();
      result = run_stages(seq, out, job, [&](const std::string& stage, size_t done, size_t total) {
        if (bars) (*bars)(stage, done, total);
        if (progress) progress(stage, done, total);
      });
    }
    if (!job.quiet) print_tracking_summary(seq, result);
    if (job.back_end) {
      if (!job.quiet) print_back_end_summary(seq, settings, result);
      if (settings.pipeline.evaluate) {
        eval::evaluate_run_folder(seq, out, job.plot, job.quiet, figure_files(job));
        if (result.loop_pass.ran) eval::evaluate_run_loops(seq, out, job.quiet);
        if (result.fusion.frames > 0)
          eval::evaluate_run_map(seq, settings.map.max_depth, out, job.quiet);
      }
      if (!job.quiet) print_outputs(out, result);
    } else {
      if (!job.quiet) print_outputs(out, result);
      if (settings.pipeline.evaluate)
        eval::evaluate_run_folder(seq, out, job.plot, job.quiet, figure_files(job));
    }
    return result.seconds;
  });
  // A view of the finished folder, written after run.json says it is complete.
  if (job.back_end && settings.report.enabled)
    write_report_page({out}, out / "report.html", settings.report, job.quiet);
  return result;
}

}  // namespace slamkit::cli
