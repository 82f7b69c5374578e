#include "io/text_table.h"

#include <cstdlib>
#include <fstream>

#include "core/error.h"

namespace slamkit {

std::vector<TableRow> read_table(const std::filesystem::path& path) {
  if (!std::filesystem::exists(path)) throw_input_error(path.string(), "file not found");
  if (std::filesystem::is_directory(path))
    throw_input_error(path.string(), "is a folder, expected a file");
  std::ifstream in(path);
  if (!in) throw_input_error(path.string(), "cannot open file");
  std::vector<TableRow> rows;
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;
    TableRow row{number, {}};
    std::string field;
    for (char ch : line) {
      if (ch == ' ' || ch == '\t' || ch == ',' || ch == '\r') {
        if (!field.empty()) row.fields.push_back(std::move(field));
        field.clear();
      } else {
        field += ch;
      }
    }
    if (!field.empty()) row.fields.push_back(std::move(field));
    rows.push_back(std::move(row));
  }
  return rows;
}

double parse_number(const std::filesystem::path& path, const TableRow& row, size_t field) {
  if (field >= row.fields.size())
    throw_input_error(path.string(), row.line, "missing field " + std::to_string(field + 1));
  const std::string& text = row.fields[field];
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0')
    throw_input_error(path.string(), row.line,
                      "field " + std::to_string(field + 1) + " is not a number: '" + text + "'");
  return value;
}

}  // namespace slamkit
