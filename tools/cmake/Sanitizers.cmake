# Instrumented builds, each in a build tree of its own (see tools/setup.sh and tools/fuzz.sh):
#   CLRT_SANITIZE  AddressSanitizer + UndefinedBehaviorSanitizer on everything (the CI's second
#                  run of the test suite; GCC or Clang);
#   CLRT_FUZZ      the libFuzzer targets of tests/fuzz, sanitized the same way (Clang only).
option(CLRT_SANITIZE "Build everything with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(CLRT_FUZZ "Build the libFuzzer targets (tests/fuzz); needs Clang" OFF)

if(CLRT_SANITIZE OR CLRT_FUZZ)
  # Every finding stops the process: a test or fuzz run cannot pass over a report.
  set(clrt_sanitizer_flags -fsanitize=address,undefined -fno-sanitize-recover=all
      -fno-omit-frame-pointer)
  add_compile_options(${clrt_sanitizer_flags})
  add_link_options(${clrt_sanitizer_flags})
endif()

if(CLRT_SANITIZE)
  # Whatever the build type: -O0 -g1 (the sanitized tree is built in every CI run) compiles in
  # 60% of the time of -O1 -g1, which took half the time of -O2 -g, and keeps line numbers in
  # reports; the host code a sanitized test runs is parsing and bookkeeping, the renders' work
  # is in the kernels. GCC's -Wmaybe-uninitialized fires on libstdc++'s <regex> with ASan,
  # falsely.
  add_compile_options(-O0 -g1 $<$<CXX_COMPILER_ID:GNU>:-Wno-maybe-uninitialized>)
endif()

if(CLRT_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "CLRT_FUZZ needs Clang (libFuzzer): configure with CXX=clang++-15")
  endif()
  # Coverage feedback for every library; only the fuzz executables link libFuzzer's main.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
