#pragma once
// What `slamkit --version` prints: the release, the commit (`git describe --always --dirty`)
// and the build type, written at build time (cmake/build_info.cmake).

namespace slamkit::cli {
extern const char* const kVersion;
extern const char* const kCommit;
extern const char* const kBuildType;
}  // namespace slamkit::cli
