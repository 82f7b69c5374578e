#include "io/path_kind.h"

#include <system_error>

#include "core/error.h"

namespace slamkit {

PathKind path_kind(const std::filesystem::path& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);
  if (status.type() == std::filesystem::file_type::not_found) return PathKind::kMissing;
  if (error) throw_input_error(path.string(), error.message());
  if (std::filesystem::is_regular_file(status)) return PathKind::kFile;
  if (std::filesystem::is_directory(status)) return PathKind::kFolder;
  return PathKind::kOther;
}

}  // namespace slamkit
