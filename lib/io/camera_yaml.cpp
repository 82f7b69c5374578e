#include "io/camera_yaml.h"

#include <yaml-cpp/yaml.h>

#include <cmath>

#include "core/error.h"
#include "io/png_file.h"
#include "io/value_range.h"
#include "io/yaml_file.h"

namespace slamkit {
namespace {

// The key's number, checked against its range (NaN and infinities are outside every range).
double read_field(const YAML::Node& root, const std::string& path, const char* key,
                  std::optional<double> fallback, const Range& range = {-kNoLimit, kNoLimit}) {
  const YAML::Node node = root[key];
  if (!node) {
    if (fallback) return *fallback;
    throw_input_error(path, std::string("missing required key '") + key + "'");
  }
  double value = 0;
  try {
    value = node.as<double>();
  } catch (const YAML::Exception&) {
    throw_input_error(path, node.Mark().line + 1, std::string("'") + key + "' is not a number");
  }
  if (!in_range(value, range))
    throw_input_error(path, node.Mark().line + 1,
                      std::string(key) + ": " + node.Scalar() + " is outside " + range_text(range));
  return value;
}

bool read_flag(const YAML::Node& root, const std::string& path, const char* key, bool fallback) {
  const YAML::Node node = root[key];
  if (!node) return fallback;
  try {
    return node.as<bool>();
  } catch (const YAML::Exception&) {
    throw_input_error(path, node.Mark().line + 1,
                      std::string("'") + key + "' is not true or false");
  }
}

// Image sides are whole pixels, no larger than any image read_png accepts.
int read_side(const YAML::Node& root, const std::string& path, const char* key, int fallback) {
  const double value = read_field(root, path, key, fallback, {1, double(kMaxImageSide)});
  if (value != std::floor(value))
    throw_input_error(path, root[key].Mark().line + 1,
                      std::string(key) + ": " + root[key].Scalar() + " is not a whole number");
  return int(value);
}

}  // namespace

Camera read_camera_yaml(const std::filesystem::path& path) {
  const std::string name = path.string();
  const YAML::Node root = load_yaml_file(path, "calibration file");
  if (!root.IsMap()) throw_input_error(name, "expected a YAML map of calibration keys");
  Camera c;
  c.name = root["name"] ? scalar_text(root["name"], name, "name") : path.stem().string();
  c.fx = read_field(root, name, "fx", std::nullopt, above(0));
  c.fy = read_field(root, name, "fy", std::nullopt, above(0));
  c.cx = read_field(root, name, "cx", std::nullopt);
  c.cy = read_field(root, name, "cy", std::nullopt);
  c.distortion.k1 = read_field(root, name, "k1", 0.0);
  c.distortion.k2 = read_field(root, name, "k2", 0.0);
  c.distortion.p1 = read_field(root, name, "p1", 0.0);
  c.distortion.p2 = read_field(root, name, "p2", 0.0);
  c.distortion.k3 = read_field(root, name, "k3", 0.0);
  c.width = read_side(root, name, "width", 640);
  c.height = read_side(root, name, "height", 480);
  c.depth_scale = read_field(root, name, "depth_scale", 5000.0, above(0));
  c.min_depth = read_field(root, name, "min_depth", 0.1, at_least(0));
  c.max_depth = read_field(root, name, "max_depth", 8.0, above(0));
  c.readout_time = read_field(root, name, "readout_time", 0.0, {0, 1});
  c.exact_depth_stamps = read_flag(root, name, "exact_depth_stamps", false);
  if (!(c.min_depth < c.max_depth))
    throw_input_error(name, "min_depth " + format_exact(c.min_depth) + " must be below max_depth " +
                                format_exact(c.max_depth));
  return c;
}

void write_camera_yaml(const std::filesystem::path& path, const Camera& c) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << c.name;
  out << YAML::Key << "fx" << YAML::Value << c.fx << YAML::Key << "fy" << YAML::Value << c.fy;
  out << YAML::Key << "cx" << YAML::Value << c.cx << YAML::Key << "cy" << YAML::Value << c.cy;
  out << YAML::Key << "k1" << YAML::Value << c.distortion.k1;
  out << YAML::Key << "k2" << YAML::Value << c.distortion.k2;
  out << YAML::Key << "p1" << YAML::Value << c.distortion.p1;
  out << YAML::Key << "p2" << YAML::Value << c.distortion.p2;
  out << YAML::Key << "k3" << YAML::Value << c.distortion.k3;
  out << YAML::Key << "width" << YAML::Value << c.width;
  out << YAML::Key << "height" << YAML::Value << c.height;
  out << YAML::Key << "depth_scale" << YAML::Value << c.depth_scale;
  out << YAML::Key << "min_depth" << YAML::Value << c.min_depth;
  out << YAML::Key << "max_depth" << YAML::Value << c.max_depth;
  // Written only when set, so that files of sensors without them stay as they were.
  if (c.readout_time > 0) out << YAML::Key << "readout_time" << YAML::Value << c.readout_time;
  if (c.exact_depth_stamps) out << YAML::Key << "exact_depth_stamps" << YAML::Value << true;
  out << YAML::EndMap;
  write_yaml_file(path, out);
}

}  // namespace slamkit
