# Run at build time (cmake -P): writes OUTPUT, a C++ file naming the commit the binary was built
# from and its build type, for `slamkit --version`. configure_file rewrites it only when the
# text changes, so a build without a new commit relinks nothing.
# Variables: SOURCE_DIR, OUTPUT, VERSION, BUILD_TYPE.
execute_process(
  COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --tags
  OUTPUT_VARIABLE commit
  OUTPUT_STRIP_TRAILING_WHITESPACE
  ERROR_QUIET
  RESULT_VARIABLE status)
if(NOT status EQUAL 0 OR commit STREQUAL "")
  set(commit "unknown commit (not a git checkout)")
endif()
if(BUILD_TYPE STREQUAL "")
  set(BUILD_TYPE "no build type")
endif()
file(WRITE "${OUTPUT}.in" [=[
// Generated at build time by cmake/build_info.cmake; do not edit.
#include "bin/build_info.h"

namespace slamkit::cli {
const char* const kVersion = "@VERSION@";
const char* const kCommit = "@commit@";
const char* const kBuildType = "@BUILD_TYPE@";
}  // namespace slamkit::cli
]=])
configure_file("${OUTPUT}.in" "${OUTPUT}" @ONLY)
