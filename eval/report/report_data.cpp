#include "eval/report/report_data.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "eval/report/base64.h"
#include "eval/report/mesh_simplification.h"

namespace slamkit::eval {
namespace {

using nlohmann::json;

std::vector<float> flatten(const std::vector<Eigen::Vector3d>& points) {
  std::vector<float> flat;
  flat.reserve(3 * points.size());
  for (const Eigen::Vector3d& p : points)
    for (int d = 0; d < 3; ++d) flat.push_back(float(p[d]));
  return flat;
}

// The estimated poses (trajectory.txt) in the page's frame, each with the ATE at its stamp when
// errors.csv has one; errors.csv's own aligned positions are the same points.
json trajectory_json(const RunFolder& run, double t0) {
  const Trajectory& est = *run.trajectory;
  std::vector<Eigen::Vector3d> positions;
  std::vector<float> seconds, ate;
  size_t e = 0;
  for (size_t i = 0; i < est.size(); ++i) {
    positions.push_back(run.to_groundtruth * est.position(i));
    seconds.push_back(float(est.stamp(i) - t0));
    if (!run.errors) continue;
    const std::vector<double>& stamps = run.errors->stamps;
    while (e + 1 < stamps.size() && stamps[e] < est.stamp(i) - 1e-6) ++e;
    // A pose errors.csv does not hold (not associated with groundtruth) has no error: NaN.
    ate.push_back(std::abs(stamps[e] - est.stamp(i)) < 1e-6 ? float(run.errors->ate_m[e])
                                                            : std::nanf(""));
  }
  json j = {{"count", est.size()},
            {"seconds", base64_of(seconds)},
            {"positions", base64_of(flatten(positions))}};
  if (run.errors) j["ate"] = base64_of(ate);
  return j;
}

// Keyframe poses as position and unit quaternion (x y z qx qy qz qw), rotated into the page's
// frame, for the camera glyphs.
json keyframes_json(const RunFolder& run) {
  const Trajectory& keyframes = *run.keyframes;
  const Eigen::Matrix3d linear = run.to_groundtruth.linear();
  const Eigen::Quaterniond rotation(linear / std::cbrt(linear.determinant()));
  std::vector<float> poses;
  for (size_t i = 0; i < keyframes.size(); ++i) {
    const Eigen::Vector3d p = run.to_groundtruth * keyframes.position(i);
    const Eigen::Quaterniond q = (rotation * keyframes.orientation(i)).normalized();
    for (double v : {p.x(), p.y(), p.z(), q.x(), q.y(), q.z(), q.w()}) poses.push_back(float(v));
  }
  return {{"count", keyframes.size()}, {"poses", base64_of(poses)}};
}

// Accepted loops as segments between their keyframes' positions.
json loops_json(const RunFolder& run) {
  json loops = json::array();
  if (!run.keyframes) return loops;
  const Trajectory& keyframes = *run.keyframes;
  const auto position = [&](double stamp) -> std::optional<Eigen::Vector3d> {
    const auto i = keyframes.nearest(stamp, 1e-4);
    if (!i) return std::nullopt;
    return run.to_groundtruth * keyframes.position(*i);
  };
  for (const LoopEdge& loop : run.loops) {
    const auto a = position(loop.keyframe_stamp), b = position(loop.loop_stamp);
    if (!a || !b) continue;  // a keyframe culled after the loop
    loops.push_back({{"from", {a->x(), a->y(), a->z()}},
                     {"to", {b->x(), b->y(), b->z()}},
                     {"verdict", loop.verdict},
                     {"stamps", {loop.keyframe_stamp, loop.loop_stamp}}});
  }
  return loops;
}

// Each lost frame at the last pose tracked before it (its own pose was not trusted).
json lost_json(const RunFolder& run) {
  std::vector<Eigen::Vector3d> positions;
  const Trajectory& est = *run.trajectory;
  for (double stamp : run.lost_stamps) {
    const auto after = std::upper_bound(est.stamps().begin(), est.stamps().end(), stamp);
    const size_t i = after == est.stamps().begin() ? 0 : size_t(after - est.stamps().begin()) - 1;
    positions.push_back(run.to_groundtruth * est.position(i));
  }
  return {{"count", positions.size()}, {"positions", base64_of(flatten(positions))}};
}

// Positions quantised to 16 bits over their bounding box ("min", "size", "positions"), as the
// page decodes them.
json quantised_positions_json(const std::vector<Eigen::Vector3f>& points) {
  Eigen::Vector3f low = Eigen::Vector3f::Constant(0), high = low;
  if (!points.empty()) {
    low = high = points.front();
    for (const Eigen::Vector3f& p : points) {
      low = low.cwiseMin(p);
      high = high.cwiseMax(p);
    }
  }
  const Eigen::Vector3f size = (high - low).cwiseMax(1e-6f);
  std::vector<uint16_t> quantised;
  quantised.reserve(3 * points.size());
  for (const Eigen::Vector3f& p : points)
    for (int d = 0; d < 3; ++d)
      quantised.push_back(uint16_t(std::lround((p[d] - low[d]) / size[d] * 65535.0f)));
  return {{"min", {low.x(), low.y(), low.z()}},
          {"size", {size.x(), size.y(), size.z()}},
          {"positions", base64_of(quantised)}};
}

Eigen::Vector3f in_page_frame(const RunFolder& run, const Eigen::Vector3f& point) {
  return (run.to_groundtruth * point.cast<double>()).cast<float>();
}

json map_json(const RunFolder& run, const PlyCloud& cloud, size_t budget) {
  const std::vector<size_t> kept = strided_subset(cloud.points.size(), budget);
  std::vector<Eigen::Vector3f> points;
  std::vector<uint8_t> colours;
  points.reserve(kept.size());
  colours.reserve(3 * kept.size());
  for (size_t i : kept) {
    points.push_back(in_page_frame(run, cloud.points[i]));
    for (uint8_t c : cloud.colours[i]) colours.push_back(c);
  }
  json j = quantised_positions_json(points);
  j["total"] = cloud.points.size();
  j["count"] = kept.size();
  j["colours"] = base64_of(colours);
  return j;
}

// The mesh within its share of the triangle budget: vertices as the map's points, triangles as
// three vertex indices each.
json mesh_json(const RunFolder& run, const PlyCloud& mesh, size_t budget) {
  const PlyCloud shown = simplify_mesh(mesh, budget);
  std::vector<Eigen::Vector3f> points;
  std::vector<uint8_t> colours;
  std::vector<uint32_t> indices;
  points.reserve(shown.points.size());
  colours.reserve(3 * shown.points.size());
  indices.reserve(3 * shown.triangles.size());
  for (size_t i = 0; i < shown.points.size(); ++i) {
    points.push_back(in_page_frame(run, shown.points[i]));
    for (uint8_t c : shown.colours[i]) colours.push_back(c);
  }
  for (const std::array<uint32_t, 3>& triangle : shown.triangles)
    for (uint32_t vertex : triangle) indices.push_back(vertex);
  json j = quantised_positions_json(points);
  j["total"] = mesh.triangles.size();
  j["count"] = shown.triangles.size();
  j["colours"] = base64_of(colours);
  j["indices"] = base64_of(indices);
  return j;
}

// tracking.csv's columns as float32 arrays, with the frame times in seconds from the start.
json frames_json(const RunFolder& run, double t0) {
  json frames = json::object();
  for (const auto& [name, values] : run.frames) {
    std::vector<float> column;
    column.reserve(values.size());
    for (double v : values) column.push_back(float(name == "stamp" ? v - t0 : v));
    frames[name == "stamp" ? "seconds" : name] = base64_of(column);
  }
  return frames;
}

// The camera's up (its -y) at the first pose, in the page's frame: the view starts level.
json up_json(const RunFolder& run) {
  if (!run.trajectory || run.trajectory->empty()) return {0, 0, 1};
  const Eigen::Vector3d up =
      (run.to_groundtruth.linear() * run.trajectory->pose(0).linear() * -Eigen::Vector3d::UnitY())
          .normalized();
  return {up.x(), up.y(), up.z()};
}

json run_json(const RunFolder& run, const PlyCloud& map, const PlyCloud& mesh, size_t point_budget,
              size_t triangle_budget) {
  double t0 = 0;
  if (run.trajectory && !run.trajectory->empty()) t0 = run.trajectory->start_time();
  const auto frame_stamps = run.frames.find("stamp");
  if (frame_stamps != run.frames.end() && !frame_stamps->second.empty())
    t0 = frame_stamps->second.front();
  json j = {{"name", run.name},
            {"dir", run.dir.string()},
            {"status", run.status},
            {"notes", run.notes},
            {"run", run.run},
            {"metrics", run.metrics},
            {"timing", run.timing},
            {"settings_yaml", run.settings_yaml},
            {"frame", run.metrics.is_null() ? "estimate" : "groundtruth"},
            {"up", up_json(run)},
            {"figures", run.figures},
            {"frames", frames_json(run, t0)},
            {"loops", loops_json(run)}};
  if (run.trajectory) {
    j["trajectory"] = trajectory_json(run, t0);
    j["lost"] = lost_json(run);
  }
  if (run.errors) j["groundtruth"] = {{"positions", base64_of(flatten(run.errors->groundtruth))}};
  if (run.keyframes) j["keyframes"] = keyframes_json(run);
  if (!map.points.empty()) j["map"] = map_json(run, map, point_budget);
  if (!mesh.triangles.empty() && triangle_budget > 0)
    j["mesh"] = mesh_json(run, mesh, triangle_budget);
  return j;
}

// `budget` shared evenly among the runs whose cloud has something to show.
size_t share_of(size_t budget, const std::vector<PlyCloud>& clouds,
                bool (*shows)(const PlyCloud&)) {
  const size_t showing = size_t(std::count_if(clouds.begin(), clouds.end(), shows));
  return showing == 0 ? 0 : budget / showing;
}

}  // namespace

std::vector<size_t> strided_subset(size_t total, size_t budget) {
  const size_t count = std::min(total, budget);
  std::vector<size_t> indices(count);
  // Index k * total / count in integers, so that no point is taken twice (k * total < total²
  // stays within 64 bits for any map that fits in memory).
  for (size_t k = 0; k < count; ++k) indices[k] = k * total / count;
  return indices;
}

json report_data(const std::vector<RunFolder>& runs, const std::vector<PlyCloud>& maps,
                 const std::vector<PlyCloud>& meshes, const ReportOptions& options) {
  const size_t point_share =
      share_of(options.point_budget, maps, [](const PlyCloud& map) { return !map.points.empty(); });
  const size_t triangle_share =
      share_of(options.mesh_triangle_budget, meshes,
               [](const PlyCloud& mesh) { return !mesh.triangles.empty(); });
  json j = {{"generator", options.generator},
            {"point_budget", options.point_budget},
            {"mesh_triangle_budget", options.mesh_triangle_budget},
            {"runs", json::array()}};
  for (size_t i = 0; i < runs.size(); ++i)
    j["runs"].push_back(run_json(runs[i], maps[i], meshes[i], point_share, triangle_share));
  return j;
}

}  // namespace slamkit::eval
