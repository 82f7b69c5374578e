// read_ply_cloud: PLY point clouds and meshes, read by hand. PCL's typed loader leaves a field
// of another type than the point type's unset (Open3D's double x, y, z came back as points at
// the origin) and reports a failure without its reason; Debian has no other PLY library but
// those inside PCL, VTK and Open3D. The whole file is mapped into memory and decoded in one
// pass: a million binary vertices take a few tens of milliseconds.
#include <algorithm>
#include <array>
#include <cmath>
#include <type_traits>

#include "core/error.h"
#include "fusion/ply_body.h"
#include "fusion/ply_cloud.h"
#include "fusion/ply_header.h"
#include "io/mapped_file.h"

namespace fs = std::filesystem;

namespace slamkit {
namespace {

using ply::Element;
using ply::Property;
using ply::ScalarType;

// Where each vertex property goes.
enum Slot { kSkip, kX, kY, kZ, kRed, kGreen, kBlue, kNx, kNy, kNz, kSlots };

struct VertexLayout {
  std::vector<Slot> slots;  // per property of the vertex element
  bool has_colour = false, has_normals = false;
  ScalarType colour_type[3] = {};
};

using NameSet = std::array<const char*, 3>;
constexpr NameSet kNormalNames = {"nx", "ny", "nz"};
constexpr NameSet kColourNames[] = {{"red", "green", "blue"},
                                    {"diffuse_red", "diffuse_green", "diffuse_blue"}};

// Whether the element has the three properties; throws when it has only some of them.
bool has_all(const Element& vertex, const NameSet& names, const std::string& file) {
  const auto present = std::count_if(names.begin(), names.end(),
                                     [&](const char* name) { return vertex.find(name) >= 0; });
  if (present > 0 && present < 3)
    throw_input_error(file, vertex.line,
                      std::string("element vertex has only some of ") + names[0] + ", " + names[1] +
                          ", " + names[2]);
  return present == 3;
}

VertexLayout vertex_layout(const Element& vertex, const std::string& file) {
  VertexLayout layout;
  layout.slots.assign(vertex.properties.size(), kSkip);
  const auto assign = [&](const char* name, Slot slot) -> const Property& {
    const int index = vertex.find(name);
    const Property& p = vertex.properties[size_t(index)];
    if (p.is_list) throw_input_error(file, p.line, std::string("vertex ") + name + " is a list");
    layout.slots[size_t(index)] = slot;
    return p;
  };
  const char* const coordinates[3] = {"x", "y", "z"};
  for (int i = 0; i < 3; ++i) {
    if (vertex.find(coordinates[i]) < 0)
      throw_input_error(file, vertex.line,
                        std::string("element vertex has no property ") + coordinates[i]);
    assign(coordinates[i], Slot(kX + i));
  }

  if (has_all(vertex, kNormalNames, file)) {
    for (int i = 0; i < 3; ++i) {
      const Property& p = assign(kNormalNames[i], Slot(kNx + i));
      if (ply::is_integer(p.type))
        throw_input_error(file, p.line,
                          std::string("normal ") + p.name + " of type " + ply::type_name(p.type) +
                              ", expected float or double");
    }
    layout.has_normals = true;
  }

  for (const NameSet& names : kColourNames) {
    if (!has_all(vertex, names, file)) continue;
    for (int i = 0; i < 3; ++i) {
      const Property& p = assign(names[i], Slot(kRed + i));
      if (p.type != ScalarType::kUint8 && p.type != ScalarType::kUint16 && ply::is_integer(p.type))
        throw_input_error(file, p.line,
                          "colour " + p.name + " of type " + ply::type_name(p.type) +
                              ", expected uchar (0..255), ushort (0..65535) or float (0..1)");
      layout.colour_type[i] = p.type;
    }
    layout.has_colour = true;
    break;
  }
  return layout;
}

// The face element's list of vertex indices, or -1 when there are no faces to read.
int face_index_list(const ply::Header& header, const std::string& file) {
  const int face = header.find("face");
  if (face < 0) return -1;
  const Element& element = header.elements[size_t(face)];
  int list = element.find("vertex_indices");
  if (list < 0) list = element.find("vertex_index");
  if (list < 0) {
    if (element.count == 0) return -1;
    throw_input_error(file, element.line, "element face has no vertex_indices list");
  }
  const Property& p = element.properties[size_t(list)];
  if (!p.is_list || !ply::is_integer(p.type))
    throw_input_error(file, p.line, "face " + p.name + " must be a list of integers");
  return list;
}

// The fewest bytes each element's rows can take: a refusal of a count the file cannot hold
// comes before any allocation for it.
void check_counts_fit(const ply::Header& header, size_t body_bytes, const std::string& file) {
  const bool ascii = header.format == ply::Format::kAscii;
  // ascii: a digit and a space or newline for each value; the file's last may lack the latter.
  uint64_t remaining = body_bytes + (ascii ? 1 : 0);
  for (const Element& element : header.elements) {
    uint64_t row = 0;
    for (const Property& p : element.properties)
      row += ascii ? 2 : ply::scalar_size(p.is_list ? p.list_count_type : p.type);
    if (row > 0 && element.count > remaining / row)
      throw_input_error(file, element.line,
                        "element " + element.name + " of " + std::to_string(element.count) +
                            " rows cannot fit in the " + std::to_string(body_bytes) +
                            " bytes after the header: the file is shorter than its header "
                            "promises");
    remaining -= element.count * row;
  }
}

uint8_t colour_channel(double value, ScalarType type) {
  if (type == ScalarType::kUint8) return uint8_t(value);
  if (type == ScalarType::kUint16) return uint8_t(uint32_t(value) >> 8);
  if (!(value > 0)) return 0;  // NaN too
  return uint8_t(std::lround(std::min(value, 1.0) * 255));
}

template <typename Body>
uint64_t list_length(Body& body, const Element& element, uint64_t row, const Property& p) {
  const double length = body.value(p.list_count_type);
  if (length < 0)
    body.fail(ply::row_name(element, row) + " has a list " + p.name + " of length " +
              std::to_string(int64_t(length)));
  return uint64_t(length);
}

template <typename Body>
void skip_element(Body& body, const Element& element) {
  if (element.count == 0) return;  // may have no property at all ("element face 0")
  if constexpr (std::is_same_v<Body, ply::BinaryBody>) {
    const bool has_list = std::any_of(element.properties.begin(), element.properties.end(),
                                      [](const Property& p) { return p.is_list; });
    if (!has_list) {
      size_t row_bytes = 0;
      for (const Property& p : element.properties) row_bytes += ply::scalar_size(p.type);
      body.skip_rows(element, element.count, row_bytes);
      return;
    }
  }
  for (uint64_t row = 0; row < element.count; ++row) {
    body.start_row(element, row);
    for (const Property& p : element.properties)
      body.skip(p.type, p.is_list ? list_length(body, element, row, p) : 1);
    body.end_row();
  }
}

template <typename Body>
void read_vertices(Body& body, const Element& vertex, const VertexLayout& layout, PlyCloud& cloud) {
  cloud.points.reserve(vertex.count);
  cloud.colours.reserve(vertex.count);
  if (layout.has_normals) cloud.normals.reserve(vertex.count);
  double v[kSlots] = {};
  for (uint64_t row = 0; row < vertex.count; ++row) {
    body.start_row(vertex, row);
    for (size_t i = 0; i < vertex.properties.size(); ++i) {
      const Property& p = vertex.properties[i];
      if (p.is_list)
        body.skip(p.type, list_length(body, vertex, row, p));
      else
        v[layout.slots[i]] = body.value(p.type);
    }
    body.end_row();
    cloud.points.emplace_back(float(v[kX]), float(v[kY]), float(v[kZ]));
    if (layout.has_normals) cloud.normals.emplace_back(float(v[kNx]), float(v[kNy]), float(v[kNz]));
    Rgb8 colour = {0, 0, 0};
    if (layout.has_colour)
      for (int c = 0; c < 3; ++c) colour[c] = colour_channel(v[kRed + c], layout.colour_type[c]);
    cloud.colours.push_back(colour);
  }
}

// Faces of more than three vertices are fanned into triangles from their first vertex.
template <typename Body>
void read_faces(Body& body, const Element& face, int index_list, uint64_t vertex_count,
                PlyCloud& cloud) {
  cloud.triangles.reserve(face.count);
  std::vector<uint32_t> polygon;
  for (uint64_t row = 0; row < face.count; ++row) {
    body.start_row(face, row);
    for (size_t i = 0; i < face.properties.size(); ++i) {
      const Property& p = face.properties[i];
      if (int(i) != index_list) {
        body.skip(p.type, p.is_list ? list_length(body, face, row, p) : 1);
        continue;
      }
      const uint64_t length = list_length(body, face, row, p);
      if (length < 3)
        body.fail(ply::row_name(face, row) + " has " + std::to_string(length) +
                  " vertices, fewer than a face's 3");
      polygon.clear();
      for (uint64_t k = 0; k < length; ++k) {
        const double index = body.value(p.type);
        if (index < 0 || index >= double(vertex_count))
          body.fail(ply::row_name(face, row) + " refers to vertex " +
                    std::to_string(int64_t(index)) + ", but the file has " +
                    std::to_string(vertex_count) + " vertices");
        polygon.push_back(uint32_t(index));
      }
      for (size_t k = 1; k + 1 < polygon.size(); ++k)
        cloud.triangles.push_back({polygon[0], polygon[k], polygon[k + 1]});
    }
    body.end_row();
  }
}

template <typename Body>
PlyCloud read_body(Body& body, const ply::Header& header, const std::string& file) {
  const int vertex = header.find("vertex");
  if (vertex < 0) throw_input_error(file, header.lines, "the PLY header has no element vertex");
  const Element& vertices = header.elements[size_t(vertex)];
  const VertexLayout layout = vertex_layout(vertices, file);
  const int index_list = face_index_list(header, file);
  PlyCloud cloud;
  for (const Element& element : header.elements) {
    if (&element == &vertices)
      read_vertices(body, element, layout, cloud);
    else if (element.name == "face" && index_list >= 0)
      read_faces(body, element, index_list, vertices.count, cloud);
    else
      skip_element(body, element);
  }
  body.finish();
  return cloud;
}

}  // namespace

PlyCloud read_ply_cloud(const fs::path& path) {
  const std::string name = path.string();
  const MappedFile file(path, "PLY file");
  const ply::Header header = ply::parse_header(file.bytes(), name);
  const std::string_view body = file.bytes().substr(header.body_offset);
  check_counts_fit(header, body.size(), name);
  if (header.format == ply::Format::kAscii) {
    ply::AsciiBody ascii(body, header.lines + 1, name);
    return read_body(ascii, header, name);
  }
  ply::BinaryBody binary(body, header.format == ply::Format::kBinaryBigEndian, name);
  return read_body(binary, header, name);
}

std::vector<Eigen::Vector3f> read_ply_points(const fs::path& path) {
  return read_ply_cloud(path).points;
}

}  // namespace slamkit
