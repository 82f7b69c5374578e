#include "pipeline/run_output.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstring>
#include <nlohmann/json.hpp>

#include "core/fingerprint.h"
#include "core/number_format.h"
#include "io/atomic_file.h"
#include "io/camera_yaml.h"
#include "settings/settings_yaml.h"
#include "io/trajectory_io.h"

namespace fs = std::filesystem;

namespace slamkit {
namespace {

StageStats stats_of(const std::string& name, std::vector<double> values) {
  StageStats s{name};
  if (values.empty()) return s;
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  s.median_ms = n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
  for (double v : values) s.mean_ms += v / double(n);
  s.max_ms = values.back();
  return s;
}

void write_tracking_csv(std::ostream& out, const RunResult& result) {
  out << "index,stamp,solver,features,matches,pairs_3d,inliers,refined,lost,failure,keyframe,"
         "similarity,reference_keyframe,decode_ms,features_ms,window_code_ms,match_ms,pose_ms,"
         "refine_ms,keyframe_ms,mapping_ms\n";
  char stamp[32];
  for (size_t i = 0; i < result.frames.size(); ++i) {
    const TrackedFrame& f = result.frames[i];
    const FrameTiming& t = result.timing[i];
    std::snprintf(stamp, sizeof stamp, "%.6f", f.stamp);
    out << f.index << ',' << stamp << ',' << solver_name(f.solver) << ',' << f.features << ','
        << f.matches << ',' << f.pairs_3d << ',' << f.inliers << ',' << int(f.refined) << ','
        << int(f.lost) << ',' << f.failure << ',' << int(f.keyframe) << ',' << f.similarity << ','
        << f.reference_keyframe << ',' << t.decode_ms << ',' << t.features_ms << ','
        << t.window_code_ms << ',' << f.match_ms << ',' << f.pose_ms << ',' << f.refine_ms << ','
        << f.keyframe_ms << ',' << t.mapping_ms << '\n';
  }
}

void write_mapping_csv(std::ostream& out, const RunResult& result) {
  out << "keyframe,frame,new_points,culled_points,fused_points,culled_keyframes,local_ba,"
         "free_keyframes,fixed_keyframes,ba_points,ba_observations,ba_iterations,ba_outliers,"
         "ba_ms,mapping_ms,ba_wait_ms\n";
  const auto& keyframes = result.map.keyframes();
  for (const MappingReport& r : result.keyframe_reports) {
    const MapAdjustment& ba = r.ba;
    out << r.keyframe << ',' << keyframes[size_t(r.keyframe)].frame_index << ',' << r.new_points
        << ',' << r.culled_points << ',' << r.fused_points << ',' << r.culled_keyframes << ','
        << int(r.ba_run) << ',' << ba.free_keyframes << ',' << ba.fixed_keyframes << ','
        << ba.points << ',' << ba.observations << ',' << ba.report.iterations << ','
        << ba.removed_observations << ',' << ba.report.seconds * 1000.0 << ',' << r.ms << ','
        << r.ba_wait_ms << '\n';
  }
}


// The stamps and the measured relative pose (the candidate in the keyframe's frame, for the
// verified rows) let the evaluator judge each loop against groundtruth (eval/loop_accuracy.h).
void write_loops_csv(std::ostream& out, const LoopPassReport& loops, const Map& map) {
  out << "keyframe,candidate,keyframe_stamp,candidate_stamp,score,min_score,"
         "consistent_neighbours,verified,matches,inliers,neighbourhood_inliers,pose_error_m,"
         "tx,ty,tz,qx,qy,qz,qw,accepted,reason\n";
  for (const LoopDecision& d : loops.decisions) {
    const Eigen::Vector3d t = d.check.T_keyframe_candidate.translation();
    const Eigen::Quaterniond q(d.check.T_keyframe_candidate.linear());
    out << d.keyframe << ',' << d.candidate << ',' << format_exact(map.keyframe(d.keyframe).stamp)
        << ',' << format_exact(map.keyframe(d.candidate).stamp) << ',' << d.score << ','
        << d.min_score << ',' << d.consistent << ',' << d.verified << ',' << d.check.matches << ','
        << d.check.inliers << ',' << d.check.neighbourhood_inliers << ',' << d.check.pose_error
        << ',' << t.x() << ',' << t.y() << ',' << t.z() << ',' << q.x() << ',' << q.y() << ','
        << q.z() << ',' << q.w() << ',' << d.check.accepted << ",\"" << d.check.reason << "\"\n";
  }
}

nlohmann::json status_json(const RunStart& run, const std::string& status) {
  return {{"status", status},
          {"version", SLAMKIT_VERSION},
          {"settings_hash", run.settings_hash},
          {"started", run.started}};
}

// What the signal handler writes, prepared beforehand: it may only call async-signal-safe
// functions (open, write, rename, unlink, _exit), so nothing is formatted or allocated there.
char g_status_path[4096];
char g_status_temporary[4096];
char g_interrupted_text[1024];  // run.json up to the signal number
size_t g_interrupted_length = 0;

void write_all(int fd, const char* data, size_t length) {
  while (length > 0) {
    const ssize_t n = ::write(fd, data, length);
    if (n <= 0) return;
    data += n;
    length -= size_t(n);
  }
}

void on_interrupt(int signal) {
  remove_pending_temporaries();
  const int fd = ::open(g_status_temporary, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0) {
    write_all(fd, g_interrupted_text, g_interrupted_length);
    char digits[8];
    int n = 0;
    for (int s = signal; n == 0 || s > 0; s /= 10) digits[n++] = char('0' + s % 10);
    while (n > 0) write_all(fd, &digits[--n], 1);
    write_all(fd, "\n}\n", 3);
    ::close(fd);
    ::rename(g_status_temporary, g_status_path);
  }
  ::_exit(128 + signal);
}

void set_interrupt_handler(void (*handler)(int)) {
  struct sigaction action {};
  action.sa_handler = handler;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void copy_text(char* to, size_t capacity, const std::string& text) {
  const size_t n = std::min(text.size(), capacity - 1);
  std::memcpy(to, text.data(), n);
  to[n] = '\0';
}

}  // namespace

nlohmann::json stage_seconds_json(const StageTimes& t) {
  return {{"prepare", t.prepare}, {"track", t.track},         {"local_ba", t.local_ba},
          {"loops", t.loops},     {"global_ba", t.global_ba}, {"refine", t.refine},
          {"fusion", t.fusion},   {"write", t.write},         {"total", t.total}};
}

RunStart begin_run_folder(const fs::path& dir, const Settings& settings, OnSignal on_signal) {
  fs::create_directories(dir);
  RunStart run{dir, fnv1a64_hex(settings_yaml_text(settings)), utc_now_iso()};
  std::string text = status_json(run, "interrupted").dump(2);
  text.erase(text.find_last_not_of("}\n") + 1);  // reopened for the signal number
  text += ",\n  \"signal\": ";
  const fs::path path = dir / "run.json";
  if (on_signal == OnSignal::kEndProcess && text.size() < sizeof g_interrupted_text &&
      path.string().size() + 4 < sizeof g_status_path) {
    copy_text(g_interrupted_text, sizeof g_interrupted_text, text);
    g_interrupted_length = text.size();
    copy_text(g_status_path, sizeof g_status_path, path.string());
    copy_text(g_status_temporary, sizeof g_status_temporary, path.string() + ".tmp");
    set_interrupt_handler(on_interrupt);
    run.handles_signals = true;
  }
  write_file_atomically(
      path, [&](std::ostream& out) { out << status_json(run, "running").dump(2) << "\n"; });
  return run;
}

void write_run_status(const RunStart& run, const StageTimes& t) {
  // Complete now: an interrupt no longer marks the folder.
  if (run.handles_signals) set_interrupt_handler(SIG_DFL);
  nlohmann::json json = status_json(run, "complete");
  json["ended"] = utc_now_iso();
  json["seconds"] = stage_seconds_json(t);
  write_file_atomically(run.dir / "run.json",
                        [&](std::ostream& out) { out << json.dump(2) << "\n"; });
}

void fill_run_folder(const RunStart& run, const std::function<StageTimes()>& work) {
  StageTimes seconds;
  try {
    seconds = work();
  } catch (const std::exception& e) {
    if (run.handles_signals) set_interrupt_handler(SIG_DFL);
    const auto* interrupted = dynamic_cast<const RunInterrupted*>(&e);
    nlohmann::json json = status_json(run, interrupted ? "interrupted" : "failed");
    if (interrupted) {
      json["signal"] = interrupted->signal;
    } else {
      json["ended"] = utc_now_iso();
      json["error"] = e.what();
    }
    write_file_atomically(run.dir / "run.json",
                          [&](std::ostream& out) { out << json.dump(2) << "\n"; });
    throw;
  }
  write_run_status(run, seconds);
}

TimingSummary summarise_timing(const RunResult& result) {
  std::vector<double> decode, features, code, match, pose, refine, keyframe, mapping, tracking;
  for (size_t i = 0; i < result.frames.size(); ++i) {
    const TrackedFrame& f = result.frames[i];
    const FrameTiming& t = result.timing[i];
    decode.push_back(t.decode_ms);
    features.push_back(t.features_ms);
    code.push_back(t.window_code_ms);
    match.push_back(f.match_ms);
    pose.push_back(f.pose_ms);
    refine.push_back(f.refine_ms);
    keyframe.push_back(f.keyframe_ms);
    if (f.keyframe) mapping.push_back(t.mapping_ms);  // per keyframe, local BA included
    tracking.push_back(t.features_ms + t.window_code_ms + f.match_ms + f.pose_ms + f.refine_ms +
                       f.keyframe_ms + t.mapping_ms);
  }
  TimingSummary s;
  s.stages = {stats_of("decode", decode),     stats_of("features", features),
              stats_of("window_code", code),  stats_of("match", match),
              stats_of("pose", pose),         stats_of("refine", refine),
              stats_of("keyframe", keyframe), stats_of("mapping", mapping)};
  s.tracking_median_ms = stats_of("tracking", tracking).median_ms;
  const double wall = result.seconds.total;
  s.frames_per_second = wall > 0 ? double(result.frames.size()) / wall : 0;
  return s;
}

std::vector<std::string> describe_failures(const RunResult& result) {
  std::vector<std::string> lines;
  const auto& frames = result.frames;
  for (size_t i = 0; i < frames.size(); ++i) {
    if (!frames[i].lost || (i > 0 && frames[i - 1].lost)) continue;
    size_t end = i;
    while (end + 1 < frames.size() && frames[end + 1].lost) ++end;
    std::string line = "frame " + std::to_string(frames[i].index);
    if (end > i)
      line = "frames " + std::to_string(frames[i].index) + "-" + std::to_string(frames[end].index);
    line += " lost (" + frames[i].failure + "), motion model used; ";
    line += end + 1 < frames.size()
                ? "tracking recovered at frame " + std::to_string(frames[end + 1].index) +
                      " after " + std::to_string(end - i + 1) + " frame(s)"
                : "not recovered before the end";
    lines.push_back(line);
  }
  return lines;
}

void write_run_outputs(const fs::path& dir, const std::string& sequence_name, const Camera& camera,
                       const Settings& settings, const RunResult& result) {
  fs::create_directories(dir);
  const std::string lost = result.lost_frames == LostFrames::kOmit
                               ? "lost frames omitted"
                               : "lost frames at the motion model's pose";
  write_tum_trajectory(dir / "trajectory.txt", result.trajectory(),
                       "slamkit trajectory of " + sequence_name + " (T_w_c; " + lost + ")");
  if (settings.optimization.local_ba.enabled || result.global_ba_run)
    write_tum_trajectory(dir / "trajectory_tracked.txt", result.tracked_trajectory(),
                         "slamkit trajectory of " + sequence_name +
                             " as tracked, before the back end's corrections; " + lost);
  write_tum_trajectory(dir / "keyframes.txt", result.keyframe_trajectory(),
                       "slamkit keyframes of " + sequence_name);
  write_file_atomically(dir / "tracking.csv",
                        [&](std::ostream& out) { write_tracking_csv(out, result); });
  write_file_atomically(dir / "mapping.csv",
                        [&](std::ostream& out) { write_mapping_csv(out, result); });
  if (result.loop_pass.ran)
    write_file_atomically(dir / "loops.csv", [&](std::ostream& out) {
      write_loops_csv(out, result.loop_pass, result.map);
    });
  write_settings_yaml(dir / "settings.yaml", settings);
  write_camera_yaml(dir / "camera.yaml", camera);
}

void write_timing_json(const fs::path& dir, const std::string& sequence_name,
                       const RunResult& result) {
  const TimingSummary timing = summarise_timing(result);
  const StageTimes& t = result.seconds;
  nlohmann::json json;
  json["sequence"] = sequence_name;
  json["frames"] = result.frames.size();
  json["keyframes"] = result.map.num_active_keyframes();
  json["culled_keyframes"] = result.map.num_culled_keyframes();
  json["threads"] = result.threads;
  json["seconds"] = stage_seconds_json(t);
  const StageTimes& cpu = result.cpu_seconds;
  json["cpu_seconds"] = {{"track", cpu.track},   {"loops", cpu.loops}, {"global_ba", cpu.global_ba},
                         {"refine", cpu.refine}, {"fusion", cpu.fusion}, {"write", cpu.write},
                         {"total", cpu.total}};
  json["peak_rss_mb"] = result.peak_rss_mb;
  json["frames_per_second"] = timing.frames_per_second;
  json["tracking_median_ms"] = timing.tracking_median_ms;
  for (const StageStats& s : timing.stages)
    json["stages"][s.name] = {
        {"median_ms", s.median_ms}, {"mean_ms", s.mean_ms}, {"max_ms", s.max_ms}};
  write_file_atomically(dir / "timing.json",
                        [&](std::ostream& out) { out << json.dump(2) << "\n"; });
}

}  // namespace slamkit
