#pragma once
// The header of a PLY file, as the format's description (Greg Turk's) and the common readers
// (rply in Open3D, MeshLab, CloudCompare) define it:
//   ply / format ascii|binary_little_endian|binary_big_endian 1.0 / comment ... / obj_info ...
//   element NAME COUNT / property TYPE NAME / property list COUNT_TYPE ITEM_TYPE NAME / ...
//   end_header
// Used by the PLY reader (ply_reader.cpp) only.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace slamkit::ply {

enum class Format { kAscii, kBinaryLittleEndian, kBinaryBigEndian };

enum class ScalarType { kInt8, kUint8, kInt16, kUint16, kInt32, kUint32, kFloat32, kFloat64 };

size_t scalar_size(ScalarType type);
bool is_integer(ScalarType type);
const char* type_name(ScalarType type);  // the format's older names: "uchar", "float", ...

struct Property {
  std::string name;
  ScalarType type = ScalarType::kFloat32;  // of the value, or of each item of a list
  bool is_list = false;
  ScalarType list_count_type = ScalarType::kUint8;  // lists only: the type of their length
  int line = 0;                                     // in the header, from 1
};

struct Element {
  std::string name;
  uint64_t count = 0;
  std::vector<Property> properties;
  int line = 0;

  // Index into properties, or -1.
  int find(std::string_view property) const;
};

struct Header {
  Format format = Format::kAscii;
  std::vector<Element> elements;  // in file order
  size_t body_offset = 0;         // of the first byte after "end_header\n"
  int lines = 0;                  // the header's, "end_header" included

  // Index into elements, or -1.
  int find(std::string_view element) const;
};

// Parses the header at the start of `bytes`. Throws InputError naming `file` and the header
// line at fault: not "ply", an unknown format or version, an unknown keyword or property type,
// a line with missing or extra words, a count that is not a number, a property outside an
// element, a property or element twice, an element with a count but no property, no
// end_header.
Header parse_header(std::string_view bytes, const std::string& file);

}  // namespace slamkit::ply
