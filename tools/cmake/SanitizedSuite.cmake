# Test programs a second time, built with AddressSanitizer + UndefinedBehaviorSanitizer in a
# tree beside this one (build/ -> build-asan/), so that the README's test command
# (`ctest --test-dir build`) runs both. The first sanitized test configures that tree and builds
# the programs below (incrementally, so its binaries are never stale); then each runs whole, as
# one CTest test "sanitized:NAME". LeakSanitizer ignores only PoCL's and LLVM's own allocations
# (tools/sanitizers/lsan.supp). Skip them with `ctest -LE sanitized`.
#
# The programs are those whose host code reads what a user hands clrt (scenes, meshes, images,
# caches, the command line) or runs a whole render through the sanitized `clrt` (test_cli,
# test_clrt_output, test_limits): that is where a memory error can come from outside. The kernel
# tests' host side is a harness, and the render, MPI and cross-device suites repeat renders the
# test_cli run already makes; built and run under ASan they took more than half of CI's time.
# `-DCLRT_SANITIZED_ALL=ON` sanitizes every test program instead.
option(CLRT_SANITIZED_SUITE "ctest also builds and runs test programs under ASan + UBSan" ON)
option(CLRT_SANITIZED_ALL "the sanitized suite runs every test program, not only the input-facing ones" OFF)
if(NOT CLRT_SANITIZED_SUITE OR CLRT_SANITIZE OR CLRT_FUZZ OR NOT CLRT_BUILD_TESTS)
  return()
endif()

get_property(clrt_test_targets GLOBAL PROPERTY CLRT_TEST_TARGETS)
if(NOT CLRT_SANITIZED_ALL)
  set(clrt_input_facing_tests
    scene_tests test_image test_img_tool test_clrt_output test_cli test_cli_words test_limits
    test_fuzz_regressions test_program_cache test_bvh test_layout)
  foreach(target IN LISTS clrt_input_facing_tests)
    if(NOT target IN_LIST clrt_test_targets)
      message(FATAL_ERROR "SanitizedSuite.cmake names ${target}, which is no test program")
    endif()
  endforeach()
  set(clrt_test_targets ${clrt_input_facing_tests})
endif()

set(clrt_sanitized_dir ${PROJECT_BINARY_DIR}-asan)
string(REPLACE ";" "," clrt_sanitized_targets "${clrt_test_targets}")
add_test(NAME sanitized:build
  COMMAND ${CMAKE_COMMAND} -DSOURCE=${PROJECT_SOURCE_DIR} -DBINARY=${clrt_sanitized_dir}
          -DCXX=${CMAKE_CXX_COMPILER} -DTARGETS=${clrt_sanitized_targets}
          -P ${PROJECT_SOURCE_DIR}/tools/cmake/build_sanitized.cmake)
set_tests_properties(sanitized:build PROPERTIES FIXTURES_SETUP clrt_sanitized LABELS sanitized)

foreach(target IN LISTS clrt_test_targets)
  get_target_property(dir ${target} BINARY_DIR)
  file(RELATIVE_PATH relative ${PROJECT_BINARY_DIR} ${dir})
  # Through `cmake -E env`: the binary exists only once sanitized:build has run.
  add_test(NAME sanitized:${target}
           COMMAND ${CMAKE_COMMAND} -E env ${clrt_sanitized_dir}/${relative}/${target}
           WORKING_DIRECTORY ${PROJECT_SOURCE_DIR})
  # A test may ask for more ASan options with the target property CLRT_ASAN_OPTIONS.
  # use_tls=0: after PoCL unloads a library with thread-local storage, LeakSanitizer's scan of
  # dynamic TLS can read a stale entry and crash ("Tracer caught signal 11"), depending only on
  # how long the environment is. Without TLS as a root the scan can only report more, not less.
  get_target_property(extra_asan_options ${target} CLRT_ASAN_OPTIONS)
  set(asan_options detect_leaks=1:detect_stack_use_after_return=1)
  if(extra_asan_options)
    string(APPEND asan_options :${extra_asan_options})
  endif()
  set_tests_properties(sanitized:${target} PROPERTIES
    FIXTURES_REQUIRED clrt_sanitized LABELS sanitized
    ENVIRONMENT "POCL_CACHE_DIR=${clrt_sanitized_dir}/pocl-cache;CLRT_CACHE_DIR=${clrt_sanitized_dir}/clrt-cache;ASAN_OPTIONS=${asan_options};LSAN_OPTIONS=suppressions=${PROJECT_SOURCE_DIR}/tools/sanitizers/lsan.supp:print_suppressions=0:use_tls=0;UBSAN_OPTIONS=print_stacktrace=1")
endforeach()
