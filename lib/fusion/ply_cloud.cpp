#include "fusion/ply_cloud.h"

#include <pcl/console/print.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <system_error>

#include "core/error.h"
#include "io/path_kind.h"

namespace fs = std::filesystem;

namespace slamkit {

fs::path temporary_path(const fs::path& path) {
  return path.parent_path() / (path.filename().string() + ".tmp");
}

void write_ply_cloud(const fs::path& path, const PlyCloud& cloud, bool binary) {
  const std::string name = path.string();
  if (cloud.points.size() != cloud.colours.size())
    throw_input_error(name, "cannot write " + std::to_string(cloud.points.size()) +
                                " points with " + std::to_string(cloud.colours.size()) +
                                " colours");
  // PCL's writer refuses an empty cloud (and readers choke on N = 0 just as often).
  if (cloud.points.empty()) throw_input_error(name, "no point to write");

  pcl::PointCloud<pcl::PointXYZRGB> out;
  out.resize(cloud.points.size());
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    pcl::PointXYZRGB& p = out[i];
    p.getVector3fMap() = cloud.points[i];
    p.r = cloud.colours[i][0];
    p.g = cloud.colours[i][1];
    p.b = cloud.colours[i][2];
  }

  std::error_code error;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), error);
  const fs::path temporary = temporary_path(path);
  // use_camera = false: no "element camera" (a viewpoint meaningless for a map) after the
  // vertices, so the file ends with them and its size is header + 15 N bytes.
  pcl::PLYWriter writer;
  int status = -1;
  try {
    status = writer.write(temporary.string(), out, binary, false);
  } catch (const std::exception&) {
    status = -1;  // pcl::io::IOException: reported below like a failed write
  }
  if (status != 0) {
    fs::remove(temporary, error);
    throw_input_error(name, "cannot write PLY file (folder missing or not writable?)");
  }
  fs::rename(temporary, path, error);
  if (error) {
    fs::remove(temporary, error);
    throw_input_error(name, "cannot move the written PLY into place: " + error.message());
  }
}

PlyCloud read_ply_cloud(const fs::path& path) {
  const std::string name = path.string();
  if (path_kind(path) != PathKind::kFile) throw_input_error(name, "PLY file not found");
  pcl::PointCloud<pcl::PointXYZRGB> in;
  int status = -1;
  // PCL prints its own parse errors and warnings (a map without colour); ours is the one line.
  pcl::console::setVerbosityLevel(pcl::console::L_ALWAYS);
  try {
    status = pcl::io::loadPLYFile(name, in);
  } catch (const std::exception&) {
    status = -1;
  }
  if (status < 0) throw_input_error(name, "not a readable PLY point cloud");
  PlyCloud cloud;
  cloud.points.reserve(in.size());
  cloud.colours.reserve(in.size());
  for (const pcl::PointXYZRGB& p : in) {
    cloud.points.push_back(p.getVector3fMap());
    cloud.colours.push_back({p.r, p.g, p.b});
  }
  return cloud;
}

std::vector<Eigen::Vector3f> read_ply_points(const fs::path& path) {
  return read_ply_cloud(path).points;
}

}  // namespace slamkit
