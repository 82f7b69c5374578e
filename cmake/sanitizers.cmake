# Instrumented builds (scripts/sanitizer_build.sh builds both in one folder for sanitize.sh and
# fuzz.sh):
#   SLAMKIT_SANITIZE  AddressSanitizer + UndefinedBehaviorSanitizer on everything (gcc or clang)
#   SLAMKIT_FUZZ      the libFuzzer targets of tests/fuzz; clang only, with the same sanitizers
option(SLAMKIT_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(SLAMKIT_FUZZ "Build the libFuzzer targets (tests/fuzz; needs clang)" OFF)

if(SLAMKIT_SANITIZE OR SLAMKIT_FUZZ)
  # A UB report aborts like an ASan one, so a test or fuzzer fails on it instead of going on.
  # -O1 (after the build type's flags, so it wins) and line tables only: instrumented code at
  # gcc's -O3 with -g1 took 2.5-4.5 times as long a file to compile as clang at -O1, a large
  # part of CI on two cores; -O1 is what the sanitizers' documentation recommends.
  add_compile_options(-O1 -fsanitize=address,undefined -fno-sanitize-recover=undefined
                      -fno-omit-frame-pointer)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    # -O1 leaves the `omp simd` loops scalar: a warning each otherwise.
    add_compile_options(-gline-tables-only -Wno-pass-failed)
  else()
    add_compile_options(-g1)
  endif()
  add_link_options(-fsanitize=address,undefined)
endif()

if(SLAMKIT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SLAMKIT_FUZZ needs clang (configure with CC=clang-14 CXX=clang++-14)")
  endif()
  # libFuzzer's coverage hooks go into the libraries the fuzz targets reach (tests/fuzz), not
  # into the engine or the unit tests: every comparison calls a hook, which slows both the
  # build and the sanitizer suites and guides no fuzzer. Only the fuzzer executables link its
  # main.
endif()
