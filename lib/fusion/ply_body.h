#pragma once
// The values after a PLY header, read in order, one row of an element at a time: BinaryBody
// for both byte orders, AsciiBody for text (one row a line). Both have the same interface, so
// the reader (ply_reader.cpp) decodes either with one template. Every value is range-checked
// and every read bounds-checked: a short or malformed body is an InputError naming the file
// (and for text the line), never a value made up.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <string_view>

#include "core/error.h"
#include "fusion/ply_header.h"

namespace slamkit::ply {

// Where the reader is, for messages: "vertex 12 of 100".
inline std::string row_name(const Element& element, uint64_t row) {
  return element.name + " " + std::to_string(row) + " of " + std::to_string(element.count);
}

class BinaryBody {
 public:
  BinaryBody(std::string_view bytes, bool big_endian, const std::string& file)
      : at_(bytes.data()),
        end_(bytes.data() + bytes.size()),
        big_endian_(big_endian),
        file_(file) {}

  void start_row(const Element& element, uint64_t row) {
    element_ = &element;
    row_ = row;
  }
  void end_row() {}

  double value(ScalarType type) {
    const size_t size = scalar_size(type);
    if (size_t(end_ - at_) < size) ends_early();
    const char* p = at_;
    at_ += size;
    switch (type) {
      case ScalarType::kInt8:
        return int8_t(p[0]);
      case ScalarType::kUint8:
        return uint8_t(p[0]);
      case ScalarType::kInt16:
        return load<int16_t, uint16_t>(p);
      case ScalarType::kUint16:
        return load<uint16_t, uint16_t>(p);
      case ScalarType::kInt32:
        return load<int32_t, uint32_t>(p);
      case ScalarType::kUint32:
        return load<uint32_t, uint32_t>(p);
      case ScalarType::kFloat32:
        return load<float, uint32_t>(p);
      case ScalarType::kFloat64:
        return load<double, uint64_t>(p);
    }
    return 0;
  }

  void skip(ScalarType type, uint64_t count) {
    const size_t size = scalar_size(type);
    if (count > size_t(end_ - at_) / size) ends_early();
    at_ += count * size;
  }

  // Rows of a fixed size (an element without lists) skipped at once.
  void skip_rows(const Element& element, uint64_t rows, size_t row_bytes) {
    if (rows > size_t(end_ - at_) / row_bytes) {
      start_row(element, size_t(end_ - at_) / row_bytes);
      ends_early();
    }
    at_ += rows * row_bytes;
  }

  void finish() const {
    if (at_ != end_)
      throw_input_error(file_, std::to_string(end_ - at_) +
                                   " bytes after the last element the header declares (a "
                                   "header that does not describe the data?)");
  }

  [[noreturn]] void fail(const std::string& message) const { throw_input_error(file_, message); }

 private:
  // The bytes as the file's byte order has them, whatever the machine's.
  template <typename T, typename Bits>
  T load(const char* p) const {
    Bits bits = 0;
    if (big_endian_)
      for (size_t i = 0; i < sizeof(Bits); ++i) bits = Bits(bits << 8 | uint8_t(p[i]));
    else
      for (size_t i = 0; i < sizeof(Bits); ++i) bits |= Bits(Bits(uint8_t(p[i])) << (8 * i));
    T value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
  }

  [[noreturn]] void ends_early() const {
    fail("the file ends inside " + row_name(*element_, row_) +
         ": it is shorter than its header promises");
  }

  const char* at_;
  const char* end_;
  bool big_endian_;
  const std::string& file_;
  const Element* element_ = nullptr;
  uint64_t row_ = 0;
};

class AsciiBody {
 public:
  // `first_line`: the file's line number of the body's first line.
  AsciiBody(std::string_view text, int first_line, const std::string& file)
      : text_(text), line_number_(first_line - 1), next_line_number_(first_line), file_(file) {}

  // Moves to the row's line, past blank lines.
  void start_row(const Element& element, uint64_t row) {
    element_ = &element;
    row_ = row;
    do {
      if (at_ >= text_.size())
        throw_input_error(file_, line_number_,
                          "the file ends before " + row_name(element, row) +
                              ": it is shorter than its header promises");
      next_line();
    } while (line_.find_first_not_of(" \t") == std::string_view::npos);
  }

  void end_row() const {
    if (line_.find_first_not_of(" \t") != std::string_view::npos)
      fail(row_name(*element_, row_) + " has more values than its element's properties");
  }

  double value(ScalarType type) {
    const std::string_view word = next_word();
    const char* first = word.data();
    const char* last = word.data() + word.size();
    if (is_integer(type)) {
      int64_t v = 0;
      const auto [end, error] = std::from_chars(first, last, v);
      if (error != std::errc() || end != last) not_a_number(word, type);
      if (v < lowest(type) || v > highest(type))
        fail(row_name(*element_, row_) + ": " + std::string(word) + " is out of range for " +
             type_name(type));
      return double(v);
    }
    double v = 0;
    const auto [end, error] = std::from_chars(first, last, v);
    if (error != std::errc() || end != last) not_a_number(word, type);
    // float values are parsed as double and rounded once more: exact for the 9 significant
    // digits that identify a float, and no refusal of a float's subnormal values.
    if (type == ScalarType::kFloat32 && std::isfinite(v) &&
        std::abs(v) > double(std::numeric_limits<float>::max()))
      fail(row_name(*element_, row_) + ": " + std::string(word) + " is out of range for float");
    return type == ScalarType::kFloat32 ? double(float(v)) : v;
  }

  void skip(ScalarType type, uint64_t count) {
    for (uint64_t i = 0; i < count; ++i) value(type);
  }

  void finish() {
    while (at_ < text_.size()) {
      next_line();
      if (line_.find_first_not_of(" \t") != std::string_view::npos)
        fail("text after the last element the header declares");
    }
  }

  [[noreturn]] void fail(const std::string& message) const {
    throw_input_error(file_, line_number_, message);
  }

 private:
  void next_line() {
    const size_t end = text_.find('\n', at_);
    line_ = text_.substr(at_, end == std::string_view::npos ? std::string_view::npos : end - at_);
    at_ = end == std::string_view::npos ? text_.size() : end + 1;
    if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
    line_number_ = next_line_number_++;
  }

  std::string_view next_word() {
    const size_t begin = line_.find_first_not_of(" \t");
    if (begin == std::string_view::npos)
      fail(row_name(*element_, row_) + " has fewer values than its element's properties");
    const size_t end = std::min(line_.find_first_of(" \t", begin), line_.size());
    const std::string_view word = line_.substr(begin, end - begin);
    line_.remove_prefix(end);
    return word;
  }

  [[noreturn]] void not_a_number(std::string_view word, ScalarType type) const {
    fail(row_name(*element_, row_) + ": \"" + std::string(word) + "\" is not a " + type_name(type) +
         " value");
  }

  static int64_t lowest(ScalarType type) {
    switch (type) {
      case ScalarType::kInt8:
        return INT8_MIN;
      case ScalarType::kInt16:
        return INT16_MIN;
      case ScalarType::kInt32:
        return INT32_MIN;
      default:
        return 0;
    }
  }
  static int64_t highest(ScalarType type) {
    switch (type) {
      case ScalarType::kInt8:
        return INT8_MAX;
      case ScalarType::kUint8:
        return UINT8_MAX;
      case ScalarType::kInt16:
        return INT16_MAX;
      case ScalarType::kUint16:
        return UINT16_MAX;
      case ScalarType::kInt32:
        return INT32_MAX;
      default:
        return UINT32_MAX;
    }
  }

  std::string_view text_;
  size_t at_ = 0;
  std::string_view line_;
  int line_number_;  // of line_, or the header's last line before the first row
  int next_line_number_;
  const std::string& file_;
  const Element* element_ = nullptr;
  uint64_t row_ = 0;
};

}  // namespace slamkit::ply
