#include "io/text_table.h"

#include <cstdlib>

#include "core/error.h"
#include "io/line_reader.h"
#include "io/path_kind.h"

namespace slamkit {

std::vector<TableRow> read_table(const std::filesystem::path& path) {
  const PathKind kind = path_kind(path);
  if (kind == PathKind::kMissing) throw_input_error(path.string(), "file not found");
  if (kind == PathKind::kFolder) throw_input_error(path.string(), "is a folder, expected a file");
  LineReader reader(path, path.string());
  std::vector<TableRow> rows;
  std::string_view line;
  while (reader.next(line)) {
    const size_t first = line.find_first_not_of(" \t\r");
    if (first == std::string_view::npos || line[first] == '#') continue;
    if (rows.size() == kMaxTableRows)
      throw_input_error(
          path.string(), reader.line_number(),
          "more than " + std::to_string(kMaxTableRows) + " rows: beyond what slamkit reads");
    TableRow row{reader.line_number(), {}};
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
  // The whole field: a NUL byte inside it would otherwise end the number early.
  if (end == text.c_str() || end != text.c_str() + text.size())
    throw_input_error(path.string(), row.line,
                      "field " + std::to_string(field + 1) + " is not a number: '" + text + "'");
  return value;
}

}  // namespace slamkit
