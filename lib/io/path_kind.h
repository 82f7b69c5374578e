#pragma once
// What a path a user gave names. std::filesystem's queries throw filesystem_error for a path
// the system refuses (a name too long, a parent folder without permission); here that is an
// InputError naming the path and the system's reason, like every other bad input.
#include <filesystem>

namespace slamkit {

enum class PathKind { kMissing, kFile, kFolder, kOther };

PathKind path_kind(const std::filesystem::path& path);

}  // namespace slamkit
