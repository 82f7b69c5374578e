#pragma once
// What a run folder holds, read for the report page (eval/report/report_page.h): each file that
// exists, and a note for each that does not. A page shows what a run has, so a missing file is
// a note, not an error; a malformed one is an InputError naming the file and line.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/trajectory.h"

namespace slamkit::eval {

// errors.csv: per pose the absolute error and both positions in the groundtruth's frame.
struct PoseErrors {
  std::vector<double> stamps;
  std::vector<double> ate_m;
  std::vector<Eigen::Vector3d> estimate;     // aligned to the groundtruth
  std::vector<Eigen::Vector3d> groundtruth;  // associated with each estimated pose
};

// An accepted loop (loops.csv), with its verdict against groundtruth when loop_check.csv has one.
struct LoopEdge {
  double keyframe_stamp = 0, loop_stamp = 0;
  std::string verdict;  // "true", "false" or "unjudged"
};

// Numeric columns of tracking.csv, by name, one value a frame.
using FrameColumns = std::map<std::string, std::vector<double>>;

struct RunFolder {
  std::filesystem::path dir;
  std::string name;           // the folder's name
  std::string status;         // run.json's status; "no run.json" without one
  nlohmann::json run;         // run.json, null without one
  nlohmann::json metrics;     // metrics.json, null without groundtruth
  nlohmann::json timing;      // timing.json
  std::string settings_yaml;  // settings.yaml's text
  std::optional<Trajectory> trajectory, keyframes;
  std::optional<PoseErrors> errors;
  // The estimate's frame into the groundtruth's (metrics.json's ATE alignment: x -> sRx + t);
  // identity without groundtruth, so the page draws in the estimate's own frame.
  Eigen::Affine3d to_groundtruth = Eigen::Affine3d::Identity();
  std::vector<LoopEdge> loops;
  FrameColumns frames;                         // tracking.csv
  std::vector<double> lost_stamps;             // frames tracking.csv marks lost
  std::map<std::string, std::string> figures;  // the evaluator's SVG plots, by file stem
  std::optional<std::filesystem::path> map;    // map.ply when it exists
  std::optional<std::filesystem::path> mesh;   // mesh.ply when it exists
  std::vector<std::string> notes;              // what is missing or incomplete, and why
};

// Reads `dir`. Throws InputError when it is not a folder, when it holds neither run.json nor
// trajectory.txt (not a run folder), or when a file it holds is malformed.
RunFolder read_run_folder(const std::filesystem::path& dir);

}  // namespace slamkit::eval
