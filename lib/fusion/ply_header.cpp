#include "fusion/ply_header.h"

#include <charconv>

#include "core/error.h"

namespace slamkit::ply {
namespace {

struct TypeName {
  const char* name;
  ScalarType type;
};

// Both spellings the format's writers use: the original names and the sized ones.
constexpr TypeName kTypeNames[] = {
    {"char", ScalarType::kInt8},      {"int8", ScalarType::kInt8},
    {"uchar", ScalarType::kUint8},    {"uint8", ScalarType::kUint8},
    {"short", ScalarType::kInt16},    {"int16", ScalarType::kInt16},
    {"ushort", ScalarType::kUint16},  {"uint16", ScalarType::kUint16},
    {"int", ScalarType::kInt32},      {"int32", ScalarType::kInt32},
    {"uint", ScalarType::kUint32},    {"uint32", ScalarType::kUint32},
    {"float", ScalarType::kFloat32},  {"float32", ScalarType::kFloat32},
    {"double", ScalarType::kFloat64}, {"float64", ScalarType::kFloat64},
};

std::vector<std::string_view> words_of(std::string_view line) {
  std::vector<std::string_view> words;
  size_t at = 0;
  while (at < line.size()) {
    if (line[at] == ' ' || line[at] == '\t') {
      ++at;
      continue;
    }
    const size_t end = line.find_first_of(" \t", at);
    words.push_back(line.substr(at, end == std::string_view::npos ? end : end - at));
    at = end == std::string_view::npos ? line.size() : end;
  }
  return words;
}

// Walks the header line by line, knowing the line number for errors.
class HeaderParser {
 public:
  HeaderParser(std::string_view bytes, const std::string& file) : bytes_(bytes), file_(file) {}

  Header parse() {
    if (!next_line() || line_ != "ply")
      throw_input_error(file_, "not a PLY file (its first line is not \"ply\")");
    bool has_format = false;
    while (next_line()) {
      const std::vector<std::string_view> words = words_of(line_);
      const std::string_view keyword = words.empty() ? std::string_view() : words[0];
      if (keyword == "comment" || keyword == "obj_info") continue;
      if (keyword == "format") {
        if (has_format) fail("a second format line");
        parse_format(words);
        has_format = true;
      } else if (keyword == "element") {
        parse_element(words);
      } else if (keyword == "property") {
        parse_property(words);
      } else if (keyword == "end_header") {
        expect_words(words, 1, "end_header");
        if (!has_format) fail("the header ends without a format line");
        check_last_element();
        header_.body_offset = at_;
        header_.lines = line_number_;
        return header_;
      } else {
        fail("unknown header line \"" + std::string(line_) + "\"");
      }
    }
    throw_input_error(file_, "the PLY header never ends (no end_header line)");
  }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw_input_error(file_, line_number_, message);
  }

  // The next line without its end ("\n" or "\r\n"); false at the end of the bytes.
  bool next_line() {
    if (at_ >= bytes_.size()) return false;
    const size_t end = bytes_.find('\n', at_);
    if (end == std::string_view::npos) {  // the header cannot end on a line without '\n'
      line_ = bytes_.substr(at_);
      at_ = bytes_.size();
    } else {
      line_ = bytes_.substr(at_, end - at_);
      at_ = end + 1;
    }
    if (!line_.empty() && line_.back() == '\r') line_.remove_suffix(1);
    ++line_number_;
    return true;
  }

  void expect_words(const std::vector<std::string_view>& words, size_t count,
                    const std::string& form) const {
    if (words.size() != count)
      fail("expected \"" + form + "\", found \"" + std::string(line_) + "\"");
  }

  void parse_format(const std::vector<std::string_view>& words) {
    expect_words(words, 3, "format ascii|binary_little_endian|binary_big_endian 1.0");
    if (words[1] == "ascii")
      header_.format = Format::kAscii;
    else if (words[1] == "binary_little_endian")
      header_.format = Format::kBinaryLittleEndian;
    else if (words[1] == "binary_big_endian")
      header_.format = Format::kBinaryBigEndian;
    else
      fail("unknown PLY format \"" + std::string(words[1]) + "\"");
    if (words[2] != "1.0") fail("unsupported PLY version \"" + std::string(words[2]) + "\"");
  }

  void parse_element(const std::vector<std::string_view>& words) {
    expect_words(words, 3, "element NAME COUNT");
    check_last_element();
    Element element;
    element.name = std::string(words[1]);
    element.line = line_number_;
    const std::string_view count = words[2];
    const auto [end, error] =
        std::from_chars(count.data(), count.data() + count.size(), element.count);
    if (error != std::errc() || end != count.data() + count.size())
      fail("element " + element.name + " has the count \"" + std::string(count) +
           "\", not a whole number");
    if (header_.find(element.name) >= 0) fail("a second element " + element.name);
    header_.elements.push_back(element);
  }

  void parse_property(const std::vector<std::string_view>& words) {
    if (header_.elements.empty()) fail("a property before any element");
    Property property;
    property.line = line_number_;
    if (words.size() >= 2 && words[1] == "list") {
      expect_words(words, 5, "property list COUNT_TYPE ITEM_TYPE NAME");
      property.is_list = true;
      property.list_count_type = scalar_type(words[2]);
      if (!is_integer(property.list_count_type))
        fail("a list's length of type " + std::string(words[2]) + ", not an integer type");
      property.type = scalar_type(words[3]);
      property.name = std::string(words[4]);
    } else {
      expect_words(words, 3, "property TYPE NAME");
      property.type = scalar_type(words[1]);
      property.name = std::string(words[2]);
    }
    Element& element = header_.elements.back();
    if (element.find(property.name) >= 0)
      fail("a second property " + property.name + " in element " + element.name);
    element.properties.push_back(property);
  }

  ScalarType scalar_type(std::string_view word) const {
    for (const TypeName& t : kTypeNames)
      if (word == t.name) return t.type;
    fail("unknown property type \"" + std::string(word) + "\"");
  }

  // A counted element without properties has rows of nothing: no reader can tell where they
  // are, and a huge count of them would take forever to skip.
  void check_last_element() const {
    if (header_.elements.empty()) return;
    const Element& last = header_.elements.back();
    if (last.count > 0 && last.properties.empty())
      throw_input_error(
          file_, last.line,
          "element " + last.name + " has " + std::to_string(last.count) + " rows but no property");
  }

  std::string_view bytes_;
  const std::string& file_;
  size_t at_ = 0;
  std::string_view line_;
  int line_number_ = 0;
  Header header_;
};

}  // namespace

size_t scalar_size(ScalarType type) {
  switch (type) {
    case ScalarType::kInt8:
    case ScalarType::kUint8:
      return 1;
    case ScalarType::kInt16:
    case ScalarType::kUint16:
      return 2;
    case ScalarType::kInt32:
    case ScalarType::kUint32:
    case ScalarType::kFloat32:
      return 4;
    case ScalarType::kFloat64:
      return 8;
  }
  return 0;
}

bool is_integer(ScalarType type) {
  return type != ScalarType::kFloat32 && type != ScalarType::kFloat64;
}

const char* type_name(ScalarType type) {
  for (const TypeName& t : kTypeNames)
    if (t.type == type) return t.name;
  return "?";
}

int Element::find(std::string_view property) const {
  for (size_t i = 0; i < properties.size(); ++i)
    if (properties[i].name == property) return int(i);
  return -1;
}

int Header::find(std::string_view element) const {
  for (size_t i = 0; i < elements.size(); ++i)
    if (elements[i].name == element) return int(i);
  return -1;
}

Header parse_header(std::string_view bytes, const std::string& file) {
  return HeaderParser(bytes, file).parse();
}

}  // namespace slamkit::ply
