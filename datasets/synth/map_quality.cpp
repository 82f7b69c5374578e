#include "datasets/synth/map_quality.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>
#include <unordered_set>

#include "core/error.h"
#include "datasets/synth/room_layout.h"
#include "io/yaml_file.h"

namespace fs = std::filesystem;

namespace slamkit::synth {
namespace {

// A cube of a regular grid, packed into one integer (21 bits an axis: +-10 km at 1 cm).
int64_t cell_key(const Eigen::Vector3i& c) {
  constexpr int64_t kOffset = 1 << 20, kMask = (1 << 21) - 1;
  return ((c.x() + kOffset) & kMask) << 42 | ((c.y() + kOffset) & kMask) << 21 |
         ((c.z() + kOffset) & kMask);
}

Eigen::Vector3i cell_of(const Eigen::Vector3d& p, double size) {
  return (p / size).array().floor().cast<int>();
}

// Map points bucketed by cubes of the search radius: every point within the radius of a
// query lies in the query's cube or one of its 26 neighbours, so the search is exact.
class PointGrid {
 public:
  PointGrid(const std::vector<Eigen::Vector3f>& points, double radius) : radius_(radius) {
    for (const Eigen::Vector3f& p : points)
      cells_[cell_key(cell_of(p.cast<double>(), radius_))].push_back(p);
  }

  bool has_point_within(const Eigen::Vector3d& q) const {
    const Eigen::Vector3i c = cell_of(q, radius_);
    const Eigen::Vector3f qf = q.cast<float>();
    const float r2 = float(radius_ * radius_);
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto it = cells_.find(cell_key(c + Eigen::Vector3i(dx, dy, dz)));
          if (it == cells_.end()) continue;
          for (const Eigen::Vector3f& p : it->second)
            if ((p - qf).squaredNorm() <= r2) return true;
        }
    return false;
  }

 private:
  double radius_;
  std::unordered_map<int64_t, std::vector<Eigen::Vector3f>> cells_;
};

// The true surface the sensor could have measured from the sampled poses, one sample per
// sample_cell cube (the first hit in view order: deterministic).
std::vector<Eigen::Vector3d> visible_surface(const SyntheticScene& scene,
                                             const std::vector<Eigen::Isometry3d>& poses,
                                             const Camera& camera, const MapQualitySettings& s,
                                             size_t* views) {
  std::vector<size_t> sampled;
  for (size_t i = 0; i < poses.size(); i += size_t(s.frame_step)) sampled.push_back(i);
  *views = sampled.size();
  const double min_cos = std::cos(s.max_incidence_deg * M_PI / 180.0);
  std::vector<std::vector<Eigen::Vector3d>> hits(sampled.size());
#pragma omp parallel for schedule(dynamic, 1)
  for (long k = 0; k < long(sampled.size()); ++k) {
    const Eigen::Isometry3d& T_w_c = poses[sampled[k]];
    for (int v = 0; v < camera.height; v += s.pixel_stride)
      for (int u = 0; u < camera.width; u += s.pixel_stride) {
        // z = 1 in the camera frame, so the hit's t is its depth.
        const Eigen::Vector3d ray_c = camera.back_project(Eigen::Vector2d(u, v), 1.0);
        const Eigen::Vector3d ray_w = T_w_c.linear() * ray_c;
        const auto hit = scene.cast_ray(T_w_c.translation(), ray_w);
        if (!hit || hit->t < s.min_depth || hit->t > s.max_depth) continue;
        if (-hit->normal.dot(ray_w.normalized()) < min_cos) continue;
        hits[k].push_back(hit->point);
      }
  }
  std::vector<Eigen::Vector3d> samples;
  std::unordered_set<int64_t> seen;
  for (const auto& view : hits)
    for (const Eigen::Vector3d& p : view)
      if (seen.insert(cell_key(cell_of(p, s.sample_cell))).second) samples.push_back(p);
  return samples;
}

// The value below which a share q of the sorted values lies (nearest rank).
double nearest_rank(const std::vector<double>& sorted, double q) {
  const size_t rank = size_t(std::ceil(q * double(sorted.size())));
  return sorted[std::clamp<size_t>(rank, 1, sorted.size()) - 1];
}

void check_settings(const MapQualitySettings& s) {
  if (s.frame_step < 1 || s.pixel_stride < 1)
    throw InputError("map quality: frame_step and pixel_stride must be at least 1");
  if (!(s.radius > 0) || !(s.sample_cell > 0) || !(s.max_depth > s.min_depth))
    throw InputError("map quality: radius and sample_cell must be positive, max_depth > min_depth");
}

}  // namespace

void write_synthetic_info(const fs::path& folder, const SequenceSpec& spec) {
  YAML::Emitter out;
  out << YAML::Comment("slamkit synthetic sequence: the recipe that rebuilds its scene");
  out << YAML::BeginMap;
  out << YAML::Key << "scene" << YAML::Value << preset_scene(spec.preset);
  out << YAML::Key << "preset" << YAML::Value << preset_name(spec.preset);
  out << YAML::Key << "frames" << YAML::Value << spec.frames;
  out << YAML::Key << "seed" << YAML::Value << spec.seed;
  if (spec.kinect) {
    out << YAML::Key << "sensor" << YAML::Value << "kinect";
    out << YAML::Key << "kinect" << YAML::Value;
    emit_kinect_settings(out, *spec.kinect);
  }
  out << YAML::EndMap;
  write_yaml_file(folder / kSyntheticInfoFile, out);
}

std::optional<SyntheticInfo> read_synthetic_info(const fs::path& folder) {
  const fs::path path = folder / kSyntheticInfoFile;
  if (!fs::exists(path)) return std::nullopt;
  const YAML::Node node = load_yaml_file(path, "synthetic sequence description");
  SyntheticInfo info;
  std::string preset;
  try {
    if (!node.IsMap()) throw_input_error(path.string(), "expected a map of scene, preset, ...");
    for (const char* key : {"scene", "preset", "frames", "seed"})
      if (!node[key]) throw_input_error(path.string(), std::string("missing '") + key + "'");
    info.scene = node["scene"].as<std::string>();
    preset = node["preset"].as<std::string>();
    info.frames = node["frames"].as<int>();
    info.seed = node["seed"].as<uint64_t>();
    const std::string sensor = node["sensor"] ? node["sensor"].as<std::string>() : "ideal";
    if (sensor != "ideal" && sensor != "kinect")
      throw_input_error(path.string(), node["sensor"].Mark().line + 1,
                        "sensor: unknown sensor '" + sensor + "' (ideal or kinect)");
    if (sensor == "kinect")
      info.kinect = node["kinect"] ? read_kinect_settings(node["kinect"], path.string())
                                   : KinectSettings();
  } catch (const YAML::Exception& e) {
    throw_input_error(path.string(), e.mark.line + 1, "YAML error: " + e.msg);
  }
  try {
    info.preset = parse_preset(preset);
  } catch (const InputError& e) {
    throw_input_error(path.string(), e.what());
  }
  return info;
}

SyntheticScene make_scene(const SyntheticInfo& info) {
  try {
    return make_named_scene(info.scene);
  } catch (const InputError& e) {
    throw InputError(std::string(kSyntheticInfoFile) + ": " + e.what());
  }
}

MapQuality evaluate_map_quality(const std::vector<Eigen::Vector3f>& map_points,
                                const SyntheticScene& scene,
                                const std::vector<Eigen::Isometry3d>& poses, const Camera& camera,
                                const MapQualitySettings& settings) {
  check_settings(settings);
  MapQuality q;
  q.settings = settings;
  q.map_points = map_points.size();

  std::vector<double> distances(map_points.size());
#pragma omp parallel for schedule(static)
  for (long i = 0; i < long(map_points.size()); ++i)
    distances[i] = scene.distance_to_surface(map_points[i].cast<double>());
  if (!distances.empty()) {
    q.accuracy_mean = std::accumulate(distances.begin(), distances.end(), 0.0) / distances.size();
    std::sort(distances.begin(), distances.end());
    const size_t mid = distances.size() / 2;
    q.accuracy_median =
        distances.size() % 2 ? distances[mid] : 0.5 * (distances[mid - 1] + distances[mid]);
    q.accuracy_p95 = nearest_rank(distances, 0.95);
    q.accuracy_max = distances.back();
  }

  const std::vector<Eigen::Vector3d> samples =
      visible_surface(scene, poses, camera, settings, &q.views);
  q.surface_samples = samples.size();
  const PointGrid grid(map_points, settings.radius);
  size_t covered = 0;
#pragma omp parallel for schedule(static) reduction(+ : covered)
  for (long i = 0; i < long(samples.size()); ++i) covered += grid.has_point_within(samples[i]);
  q.covered_samples = covered;
  q.completeness = samples.empty() ? 0.0 : double(covered) / double(samples.size());
  return q;
}

void add_map_quality_json(nlohmann::json& metrics, const MapQuality& q) {
  const MapQualitySettings& s = q.settings;
  metrics["map"] = {{"points", q.map_points},
                    {"accuracy",
                     {{"mean", q.accuracy_mean},
                      {"median", q.accuracy_median},
                      {"p95", q.accuracy_p95},
                      {"max", q.accuracy_max}}},
                    {"completeness", q.completeness},
                    {"surface_samples", q.surface_samples},
                    {"covered_samples", q.covered_samples},
                    {"views", q.views},
                    {"settings",
                     {{"frame_step", s.frame_step},
                      {"pixel_stride", s.pixel_stride},
                      {"min_depth", s.min_depth},
                      {"max_depth", s.max_depth},
                      {"max_incidence_deg", s.max_incidence_deg},
                      {"sample_cell", s.sample_cell},
                      {"radius", s.radius}}}};
  if (q.mesh_triangles > 0) metrics["map"]["mesh_triangles"] = q.mesh_triangles;
}

}  // namespace slamkit::synth
