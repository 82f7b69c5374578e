// write_ply_cloud: PLY files written by hand, in the plainest header every reader takes
// (MeshLab, CloudCompare, Open3D, PCL, our own reader), with normals and faces when the cloud
// has them. The bytes depend on the cloud alone: the same map gives the same file.
#include <charconv>
#include <cstring>
#include <ostream>
#include <system_error>

#include "core/error.h"
#include "fusion/ply_cloud.h"
#include "io/atomic_file.h"

namespace fs = std::filesystem;

namespace slamkit {
namespace {

void check_cloud(const PlyCloud& cloud, const std::string& name) {
  const size_t n = cloud.points.size();
  if (cloud.colours.size() != n)
    throw_input_error(name, "cannot write " + std::to_string(n) + " points with " +
                                std::to_string(cloud.colours.size()) + " colours");
  if (!cloud.normals.empty() && cloud.normals.size() != n)
    throw_input_error(name, "cannot write " + std::to_string(n) + " points with " +
                                std::to_string(cloud.normals.size()) + " normals");
  // Readers choke on an element vertex 0 as often as not.
  if (n == 0) throw_input_error(name, "no point to write");
  for (size_t t = 0; t < cloud.triangles.size(); ++t)
    for (const uint32_t index : cloud.triangles[t])
      if (index >= n || index > uint32_t(INT32_MAX))  // written as int
        throw_input_error(name, "cannot write triangle " + std::to_string(t) +
                                    ": it refers to vertex " + std::to_string(index) + " of " +
                                    std::to_string(n));
}

std::string header_text(const PlyCloud& cloud, bool binary) {
  std::string h = "ply\n";
  h += binary ? "format binary_little_endian 1.0\n" : "format ascii 1.0\n";
  h += "element vertex " + std::to_string(cloud.points.size()) + "\n";
  h += "property float x\nproperty float y\nproperty float z\n";
  if (!cloud.normals.empty()) h += "property float nx\nproperty float ny\nproperty float nz\n";
  h += "property uchar red\nproperty uchar green\nproperty uchar blue\n";
  if (!cloud.triangles.empty()) {
    h += "element face " + std::to_string(cloud.triangles.size()) + "\n";
    h += "property list uchar int vertex_indices\n";
  }
  return h + "end_header\n";
}

// Rows gathered in blocks of about a megabyte: a big map is never held twice in memory.
class BlockWriter {
 public:
  explicit BlockWriter(std::ostream& out) : out_(out) { block_.reserve(kBlock + 256); }
  ~BlockWriter() { flush(); }

  void uint8(uint8_t v) { block_.push_back(char(v)); }
  void uint32_le(uint32_t v) {
    for (int i = 0; i < 4; ++i) block_.push_back(char(v >> (8 * i)));
  }
  void float_le(float v) {
    uint32_t bits;
    std::memcpy(&bits, &v, 4);
    uint32_le(bits);
  }
  // The shortest text that reads back as the same float.
  template <typename T>
  void text(T v, char after) {
    char digits[32];
    const std::to_chars_result r = std::to_chars(digits, digits + sizeof digits, v);
    block_.append(digits, r.ptr);
    block_.push_back(after);
  }
  void end_row() {
    if (block_.size() >= kBlock) flush();
  }

 private:
  static constexpr size_t kBlock = 1 << 20;
  void flush() {
    out_.write(block_.data(), std::streamsize(block_.size()));
    block_.clear();
  }
  std::ostream& out_;
  std::string block_;
};

void write_binary_body(BlockWriter& out, const PlyCloud& cloud) {
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    for (int k = 0; k < 3; ++k) out.float_le(cloud.points[i][k]);
    if (!cloud.normals.empty())
      for (int k = 0; k < 3; ++k) out.float_le(cloud.normals[i][k]);
    for (int k = 0; k < 3; ++k) out.uint8(cloud.colours[i][k]);
    out.end_row();
  }
  for (const std::array<uint32_t, 3>& triangle : cloud.triangles) {
    out.uint8(3);
    for (const uint32_t index : triangle) out.uint32_le(index);
    out.end_row();
  }
}

void write_ascii_body(BlockWriter& out, const PlyCloud& cloud) {
  for (size_t i = 0; i < cloud.points.size(); ++i) {
    for (int k = 0; k < 3; ++k) out.text(cloud.points[i][k], ' ');
    if (!cloud.normals.empty())
      for (int k = 0; k < 3; ++k) out.text(cloud.normals[i][k], ' ');
    for (int k = 0; k < 3; ++k) out.text(int(cloud.colours[i][k]), k < 2 ? ' ' : '\n');
    out.end_row();
  }
  for (const std::array<uint32_t, 3>& triangle : cloud.triangles) {
    out.text(3, ' ');
    for (int k = 0; k < 3; ++k) out.text(triangle[k], k < 2 ? ' ' : '\n');
    out.end_row();
  }
}

}  // namespace

fs::path temporary_path(const fs::path& path) {
  return path.parent_path() / (path.filename().string() + ".tmp");
}

void write_ply_cloud(const fs::path& path, const PlyCloud& cloud, bool binary) {
  const std::string name = path.string();
  check_cloud(cloud, name);
  std::error_code ignored;  // a folder that cannot be made fails the write below, naming the path
  if (path.has_parent_path()) fs::create_directories(path.parent_path(), ignored);
  // write_file_atomically writes temporary_path(path) and renames it into place.
  write_file_atomically(path, [&](std::ostream& out) {
    out << header_text(cloud, binary);
    BlockWriter block(out);
    if (binary)
      write_binary_body(block, cloud);
    else
      write_ascii_body(block, cloud);
  });
}

}  // namespace slamkit
