#include "eval/loop_accuracy.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/text_table.h"

namespace slamkit::eval {
namespace {

constexpr double kMaxStampDifference = 0.02;  // as the benchmark's association

size_t column(const std::filesystem::path& path, const TableRow& header, const std::string& name) {
  const auto it = std::find(header.fields.begin(), header.fields.end(), name);
  if (it == header.fields.end())
    throw_input_error(path.string(), header.line, "no column '" + name + "' in the header");
  return size_t(it - header.fields.begin());
}

double angle_deg(const Eigen::Isometry3d& d) {
  return Eigen::AngleAxisd(d.rotation()).angle() * 180.0 / M_PI;
}

bool within(const Eigen::Isometry3d& d, double max_m, double max_deg) {
  return d.translation().norm() <= max_m && angle_deg(d) <= max_deg;
}

}  // namespace

std::vector<AcceptedLoop> read_accepted_loops(const std::filesystem::path& loops_csv) {
  const std::vector<TableRow> rows = read_table(loops_csv);
  if (rows.empty()) throw_input_error(loops_csv.string(), "empty: no header line");
  // The columns read, wherever the header puts them.
  constexpr std::array<const char*, 10> kNames = {
      "accepted", "keyframe_stamp", "candidate_stamp", "tx", "ty", "tz", "qx", "qy", "qz", "qw"};
  std::array<size_t, kNames.size()> at{};
  for (size_t i = 0; i < kNames.size(); ++i) at[i] = column(loops_csv, rows.front(), kNames[i]);
  const size_t last = *std::max_element(at.begin(), at.end());
  std::vector<AcceptedLoop> loops;
  for (size_t r = 1; r < rows.size(); ++r) {
    const TableRow& row = rows[r];
    if (row.fields.size() <= last)
      throw_input_error(loops_csv.string(), row.line, "fewer fields than the header names");
    std::array<double, kNames.size()> v{};
    for (size_t i = 0; i < kNames.size(); ++i) v[i] = parse_number(loops_csv, row, at[i]);
    if (v[0] == 0) continue;
    AcceptedLoop loop{v[1], v[2]};
    const Eigen::Quaterniond q(v[9], v[6], v[7], v[8]);
    if (!(std::abs(q.norm() - 1) < 1e-3))
      throw_input_error(loops_csv.string(), row.line, "the rotation is not a unit quaternion");
    loop.measured.linear() = q.normalized().toRotationMatrix();
    loop.measured.translation() = Eigen::Vector3d(v[3], v[4], v[5]);
    loops.push_back(loop);
  }
  return loops;
}

std::vector<RevisitEpisode> read_revisit_episodes(const std::filesystem::path& revisits_txt) {
  std::vector<RevisitEpisode> episodes;
  double previous_frame = -2;
  for (const TableRow& row : read_table(revisits_txt)) {
    if (row.fields.size() != 6)
      throw_input_error(revisits_txt.string(), row.line,
                        "expected 'later first last later_stamp first_stamp last_stamp'");
    const double frame = parse_number(revisits_txt, row, 0);
    const double stamp = parse_number(revisits_txt, row, 3);
    if (frame == previous_frame + 1)
      episodes.back().last_stamp = stamp;
    else
      episodes.push_back({stamp, stamp});
    previous_frame = frame;
  }
  return episodes;
}

const char* to_string(LoopVerdict verdict) {
  switch (verdict) {
    case LoopVerdict::kTrue:
      return "true";
    case LoopVerdict::kFalse:
      return "false";
    case LoopVerdict::kUnjudged:
      return "unjudged";
  }
  return "unjudged";
}

std::optional<double> LoopAccuracy::precision() const {
  const int judged = accepted - unjudged;
  if (judged == 0) return accepted == 0 ? std::optional<double>(1.0) : std::nullopt;
  return double(true_loops) / judged;
}

std::optional<double> LoopAccuracy::recall() const {
  if (!episodes || *episodes == 0) return std::nullopt;
  return double(episodes_found) / *episodes;
}

LoopAccuracy judge_loops(const std::vector<AcceptedLoop>& loops, const Trajectory& groundtruth,
                         const std::optional<std::vector<RevisitEpisode>>& episodes,
                         const LoopCriteria& criteria) {
  LoopAccuracy result;
  result.accepted = int(loops.size());
  std::vector<double> true_stamps;
  for (const AcceptedLoop& loop : loops) {
    JudgedLoop& judged = result.loops.emplace_back(JudgedLoop{loop.stamp, loop.loop_stamp});
    const auto a = groundtruth.nearest(loop.stamp, kMaxStampDifference);
    const auto b = groundtruth.nearest(loop.loop_stamp, kMaxStampDifference);
    if (!a || !b) {
      ++result.unjudged;
      continue;
    }
    const Eigen::Isometry3d truth = groundtruth.pose(*a).inverse() * groundtruth.pose(*b);
    result.same_place += within(truth, criteria.max_distance_m, criteria.max_angle_deg);
    const Eigen::Isometry3d error = truth.inverse() * loop.measured;
    judged.error_m = error.translation().norm();
    judged.error_deg = angle_deg(error);
    judged.verdict = LoopVerdict::kFalse;
    if (within(error, criteria.max_error_m, criteria.max_error_deg)) {
      judged.verdict = LoopVerdict::kTrue;
      ++result.true_loops;
      true_stamps.push_back(loop.stamp);
    }
  }
  if (episodes) {
    result.episodes = int(episodes->size());
    for (const RevisitEpisode& e : *episodes)
      result.episodes_found += std::any_of(true_stamps.begin(), true_stamps.end(), [&](double t) {
        return t >= e.first_stamp - 1e-6 && t <= e.last_stamp + 1e-6;
      });
  }
  return result;
}

void write_loop_check_csv(const std::filesystem::path& path, const LoopAccuracy& accuracy) {
  write_file_atomically(path, [&](std::ostream& out) {
    out << "keyframe_stamp,loop_stamp,verdict,error_m,error_deg\n";
    char line[160];
    for (const JudgedLoop& loop : accuracy.loops) {
      std::snprintf(line, sizeof line, "%.6f,%.6f,%s,%.6f,%.4f\n", loop.stamp, loop.loop_stamp,
                    to_string(loop.verdict), loop.error_m, loop.error_deg);
      out << line;
    }
  });
}

}  // namespace slamkit::eval
