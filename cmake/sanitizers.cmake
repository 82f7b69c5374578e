# Instrumented builds, each in a build folder of its own (scripts/test.sh, scripts/fuzz.sh):
#   SLAMKIT_SANITIZE  AddressSanitizer + UndefinedBehaviorSanitizer on everything (gcc or clang)
#   SLAMKIT_FUZZ      the libFuzzer targets of tests/fuzz; clang only, with the same sanitizers
option(SLAMKIT_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(SLAMKIT_FUZZ "Build the libFuzzer targets (tests/fuzz; needs clang)" OFF)

if(SLAMKIT_SANITIZE OR SLAMKIT_FUZZ)
  # A UB report aborts like an ASan one, so a test or fuzzer fails on it instead of going on.
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer -g1)  # -g1: line tables for reports, less to compile
  add_link_options(-fsanitize=address,undefined)
endif()

if(SLAMKIT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SLAMKIT_FUZZ needs clang (configure with CC=clang-14 CXX=clang++-14)")
  endif()
  # The library gets libFuzzer's coverage hooks; only the fuzzer executables link its main.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
