#pragma once
// How good a point-cloud map is, judged against the synthetic scene it was made from:
// accuracy (how far map points lie from the true surfaces) and completeness (how much of the
// surface the cameras saw the map covers). Also how tools recognise a synthetic sequence
// (synthetic.yaml, written by write_sequence) and rebuild its scene.
#include <Eigen/Geometry>
#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/camera.h"
#include "datasets/synth/scene.h"
#include "datasets/synth/sequence_writer.h"

namespace slamkit::synth {

// synthetic.yaml in a sequence folder: the recipe that rebuilds the scene.
//   scene: furnished_room   preset: desk   frames: 600   seed: 1
// and for the kinect sensor also `sensor: kinect` and `kinect: {effects: ..., settings}`
// (without them the sensor was the ideal one).
inline constexpr const char* kSyntheticInfoFile = "synthetic.yaml";

struct SyntheticInfo {
  std::string scene = "furnished_room";  // preset_scene(preset), for make_named_scene
  Preset preset = Preset::kDesk;
  int frames = 0;
  uint64_t seed = 0;
  std::optional<KinectSettings> kinect;  // nullopt: the ideal sensor
};

// Throws InputError naming the file when it cannot be written.
void write_synthetic_info(const std::filesystem::path& folder, const SequenceSpec& spec);
// nullopt when the folder has no synthetic.yaml (not a synthetic sequence); InputError naming
// the file when it is malformed.
std::optional<SyntheticInfo> read_synthetic_info(const std::filesystem::path& folder);
// The scene the info names; InputError for an unknown scene.
SyntheticScene make_scene(const SyntheticInfo& info);

struct MapQualitySettings {
  // The visible true surface: rays cast from every frame_step-th groundtruth pose through
  // every pixel_stride-th pixel, keeping hits the sensor could measure (depth within
  // [min_depth, max_depth], incidence below max_incidence_deg; SensorModel's defaults, and
  // FusionSettings::max_depth).
  int frame_step = 10;
  int pixel_stride = 8;
  double min_depth = 0.4;
  double max_depth = 3.0;
  double max_incidence_deg = 78.0;
  // Hits are kept once per cube of this size, so surface seen by many frames counts once
  // and completeness is a share of area, not of views.
  double sample_cell = 0.01;
  double radius = 0.02;  // a surface sample is covered by a map point this close
};

struct MapQuality {
  size_t map_points = 0;
  // The map was a mesh of this many triangles, judged as map_points samples of its surface
  // (set by map-eval; 0: a point cloud, judged as its points).
  size_t mesh_triangles = 0;
  // Accuracy: distance of each map point to the nearest true surface, metres.
  double accuracy_mean = 0, accuracy_median = 0, accuracy_p95 = 0, accuracy_max = 0;
  // Completeness: covered / surface_samples.
  size_t surface_samples = 0, covered_samples = 0;
  double completeness = 0;
  size_t views = 0;  // poses the surface was sampled from
  MapQualitySettings settings;
};

// `poses` are the groundtruth T_w_c of the sequence's frames in order (every frame_step-th
// is used); `camera` is the sequence's (pinhole rays: synthetic cameras have no distortion).
MapQuality evaluate_map_quality(const std::vector<Eigen::Vector3f>& map_points,
                                const SyntheticScene& scene,
                                const std::vector<Eigen::Isometry3d>& poses, const Camera& camera,
                                const MapQualitySettings& settings = {});

// Sets metrics["map"] (a run's metrics.json) to the numbers and the settings behind them:
// {"points", "accuracy": {"mean", "median", "p95", "max"}, "completeness", "surface_samples",
//  "covered_samples", "views", "settings": {...}}, and "mesh_triangles" for a mesh; distances
// in metres.
void add_map_quality_json(nlohmann::json& metrics, const MapQuality& quality);

}  // namespace slamkit::synth
