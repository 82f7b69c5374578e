#pragma once
// Lines of a text file, read in large blocks (a million-pose trajectory is 83 MB; getline and a
// string per line made reading it take seconds). A line longer than kMaxLineBytes is an
// InputError naming the file and line: no text format slamkit reads has such lines, and
// without the limit a file with no newline would be held whole in memory.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace slamkit {

constexpr size_t kMaxLineBytes = 64 * 1024;

class LineReader {
 public:
  // `name` is how errors name the file. Throws InputError when it cannot be opened.
  LineReader(const std::filesystem::path& path, std::string name);

  // The next line without its '\n' (valid until the next call); false at the end of the file.
  bool next(std::string_view& line);
  int line_number() const { return line_number_; }  // of the line last returned, from 1

 private:
  std::string name_;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
  std::vector<char> buffer_;
  size_t begin_ = 0, end_ = 0;
  bool eof_ = false;
  int line_number_ = 0;
};

}  // namespace slamkit
