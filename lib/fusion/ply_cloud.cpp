#include "fusion/ply_cloud.h"

#include <pcl/PCLPointCloud2.h>
#include <pcl/console/print.h>
#include <pcl/io/ply_io.h>
#include <pcl/point_types.h>

#include <cstring>
#include <system_error>

#include "core/error.h"
#include "io/path_kind.h"

namespace fs = std::filesystem;

namespace slamkit {
namespace {

pcl::PCLPointCloud2 packed_xyzrgb(const PlyCloud& cloud) {
  pcl::PCLPointCloud2 out;
  for (const char* name : {"x", "y", "z", "rgb"}) {
    pcl::PCLPointField field;
    field.name = name;
    field.offset = uint32_t(4 * out.fields.size());
    field.datatype = pcl::PCLPointField::FLOAT32;  // PCL's rgb: a packed 0x00RRGGBB word
    field.count = 1;
    out.fields.push_back(field);
  }
  out.point_step = 16;
  out.width = uint32_t(cloud.points.size());
  out.height = 1;
  out.row_step = out.point_step * out.width;
  out.is_dense = true;
  out.data.resize(size_t(out.row_step));
  uint8_t* at = out.data.data();
  for (size_t i = 0; i < cloud.points.size(); ++i, at += out.point_step) {
    std::memcpy(at, cloud.points[i].data(), 12);
    const Rgb8& c = cloud.colours[i];
    const uint32_t rgb = uint32_t(c[0]) << 16 | uint32_t(c[1]) << 8 | uint32_t(c[2]);
    std::memcpy(at + 12, &rgb, 4);
  }
  return out;
}

}  // namespace

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

  // Packed straight into the writer's blob (x, y, z, rgb: 16 bytes a point) rather than through
  // pcl::PointCloud<PointXYZRGB>, whose 32-byte points the writer would copy into a blob of
  // the same size again: on a 2.6-million-point map that was 160 MB held while writing.
  const pcl::PCLPointCloud2 out = packed_xyzrgb(cloud);

  std::error_code error;
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), error);
  const fs::path temporary = temporary_path(path);
  // use_camera = false: no "element camera" (a viewpoint meaningless for a map) after the
  // vertices, so the file ends with them and its size is header + 15 N bytes.
  pcl::PLYWriter writer;
  int status = -1;
  try {
    status = writer.write(temporary.string(), out, Eigen::Vector4f::Zero(),
                          Eigen::Quaternionf::Identity(), binary, false);
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
