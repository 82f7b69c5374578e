#pragma once
// Reads the whitespace tables TUM uses (rgb.txt, depth.txt, groundtruth.txt, trajectories):
// '#' starts a comment line, blank lines are skipped, fields are split on spaces, tabs and
// commas (as the benchmark's read_file_list does), CRLF line ends are accepted.
#include <filesystem>
#include <string>
#include <vector>

namespace slamkit {

struct TableRow {
  int line = 0;  // 1-based line number in the file
  std::vector<std::string> fields;
};

// A list of a million frames reads in about 150 MB; a table holds at most this many rows (18
// hours of frames at 30 Hz), and its lines at most kMaxLineBytes (line_reader.h).
constexpr size_t kMaxTableRows = 2'000'000;

// Throws InputError when the file cannot be opened, and for a table beyond those limits.
std::vector<TableRow> read_table(const std::filesystem::path& path);

// Parses a whole field as a double; throws InputError naming path and line otherwise.
// Non-finite spellings ("nan", "inf") parse: callers decide what to do with them.
double parse_number(const std::filesystem::path& path, const TableRow& row, size_t field);

}  // namespace slamkit
