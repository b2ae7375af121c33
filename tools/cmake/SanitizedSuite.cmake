# The test suite a second time, built with AddressSanitizer + UndefinedBehaviorSanitizer in a
# tree beside this one (build/ -> build-asan/), so that the README's test command
# (`ctest --test-dir build`) runs both. The first sanitized test configures and builds that tree
# (incrementally, so its binaries are never stale); then each test binary runs whole, as one
# CTest test "sanitized:NAME". LeakSanitizer ignores only PoCL's and LLVM's own allocations
# (tools/sanitizers/lsan.supp). Skip them with `ctest -LE sanitized`.
option(CLRT_SANITIZED_SUITE "ctest also builds and runs the suite under ASan + UBSan" ON)
if(NOT CLRT_SANITIZED_SUITE OR CLRT_SANITIZE OR CLRT_FUZZ OR NOT CLRT_BUILD_TESTS)
  return()
endif()

set(clrt_sanitized_dir ${PROJECT_BINARY_DIR}-asan)
add_test(NAME sanitized:build
  COMMAND ${CMAKE_COMMAND} -DSOURCE=${PROJECT_SOURCE_DIR} -DBINARY=${clrt_sanitized_dir}
          -DCXX=${CMAKE_CXX_COMPILER} -P ${PROJECT_SOURCE_DIR}/tools/cmake/build_sanitized.cmake)
set_tests_properties(sanitized:build PROPERTIES FIXTURES_SETUP clrt_sanitized LABELS sanitized)

get_property(clrt_test_targets GLOBAL PROPERTY CLRT_TEST_TARGETS)
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
