#pragma once
// A whole file's bytes, mapped read-only into memory (POSIX mmap), for readers that decode
// large files in place: no copy, and no zero-filled buffer to fault in first (on a busy
// virtual machine reading a 51 MB PLY into a string took 0.4 s, mapping it 0.07 s). The file
// must not be truncated while mapped (slamkit's writers replace files by renaming).
#include <filesystem>
#include <string>
#include <string_view>

namespace slamkit {

class MappedFile {
 public:
  // Throws InputError naming the path when it is missing ("<what> not found"), not a regular
  // file, or cannot be opened or mapped.
  MappedFile(const std::filesystem::path& path, const std::string& what);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::string_view bytes() const { return {static_cast<const char*>(data_), size_}; }

 private:
  void* data_ = nullptr;  // null for an empty file
  size_t size_ = 0;
};

}  // namespace slamkit
