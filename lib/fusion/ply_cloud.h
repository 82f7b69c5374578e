#pragma once
// Coloured point clouds as PLY files, read and written through PCL (inside ply_cloud.cpp only,
// so callers see plain Eigen types). The files are what Open3D, CloudCompare and MeshLab read:
//   ply / format binary_little_endian 1.0 (or ascii 1.0) / comment, obj_info lines /
//   element vertex N / property float x, y, z / property uchar red, green, blue /
//   element face 0 / end_header, then N vertices (15 bytes each in binary).
// ASCII files carry the 6 significant digits PCL's writer prints.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace slamkit {

using Rgb8 = std::array<uint8_t, 3>;  // red, green, blue

struct PlyCloud {
  std::vector<Eigen::Vector3f> points;
  std::vector<Rgb8> colours;             // one per point
  std::vector<Eigen::Vector3f> normals;  // one per point, or none
  // Faces as vertex index triples (a mesh); none for a point cloud.
  std::vector<std::array<uint32_t, 3>> triangles;
};

// Writes to a temporary file in the same folder (created if missing) and renames it into
// place, so a reader never sees half a file. Throws InputError naming the path when the
// folder or the file cannot be written, or when points and colours differ in number.
void write_ply_cloud(const std::filesystem::path& path, const PlyCloud& cloud, bool binary = true);

// Throws InputError naming the path when the file is missing or not a PLY point cloud.
// Colours are 0 when the file has none.
PlyCloud read_ply_cloud(const std::filesystem::path& path);
std::vector<Eigen::Vector3f> read_ply_points(const std::filesystem::path& path);

// The temporary name write_ply_cloud (and fuse_map) write before renaming: "<name>.tmp" in
// the same folder, so the rename never crosses file systems.
std::filesystem::path temporary_path(const std::filesystem::path& path);

}  // namespace slamkit
