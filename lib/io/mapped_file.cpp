#include "io/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"
#include "io/path_kind.h"

namespace slamkit {

MappedFile::MappedFile(const std::filesystem::path& path, const std::string& what) {
  const std::string name = path.string();
  const PathKind kind = path_kind(path);
  if (kind == PathKind::kMissing) throw_input_error(name, what + " not found");
  if (kind != PathKind::kFile) throw_input_error(name, "not a file, expected a " + what);
  const int fd = ::open(name.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw_input_error(name, "cannot open the " + what + ": " + std::strerror(errno));
  struct stat status {};
  if (::fstat(fd, &status) != 0) {
    const int error = errno;
    ::close(fd);
    throw_input_error(name, "cannot read the " + what + ": " + std::strerror(error));
  }
  size_ = size_t(status.st_size);
  if (size_ > 0) {
    // Populated at once: the reader walks every byte anyway.
    data_ = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
    if (data_ == MAP_FAILED) {
      const int error = errno;
      data_ = nullptr;
      ::close(fd);
      throw_input_error(name, "cannot read the " + what + ": " + std::strerror(error));
    }
  }
  ::close(fd);  // the mapping stays valid
}

MappedFile::~MappedFile() {
  if (data_) ::munmap(data_, size_);
}

}  // namespace slamkit
