#include "io/line_reader.h"

#include <cstring>

#include "core/error.h"

namespace slamkit {

LineReader::LineReader(const std::filesystem::path& path, std::string name)
    : name_(std::move(name)), file_(std::fopen(path.c_str(), "rb"), &std::fclose) {
  if (!file_) throw_input_error(name_, "cannot open file");
  buffer_.resize(2 * kMaxLineBytes);  // a whole line always fits beside the partial one
}

bool LineReader::next(std::string_view& line) {
  for (;;) {
    const char* start = buffer_.data() + begin_;
    const void* newline = std::memchr(start, '\n', end_ - begin_);
    const size_t length =
        newline ? size_t(static_cast<const char*>(newline) - start) : end_ - begin_;
    if (length > kMaxLineBytes)
      throw_input_error(name_, line_number_ + 1,
                        "line longer than " + std::to_string(kMaxLineBytes) +
                            " bytes: not a text file of this kind");
    if (newline || (eof_ && length > 0)) {
      line = std::string_view(start, length);
      begin_ += length + (newline ? 1 : 0);
      ++line_number_;
      return true;
    }
    if (eof_) return false;
    // Keep the partial line, refill behind it; the buffer holds twice the longest line.
    std::memmove(buffer_.data(), start, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
    const size_t got = std::fread(buffer_.data() + end_, 1, buffer_.size() - end_, file_.get());
    end_ += got;
    if (got == 0) {
      if (std::ferror(file_.get())) throw_input_error(name_, "read error");
      eof_ = true;
    }
  }
}

}  // namespace slamkit
