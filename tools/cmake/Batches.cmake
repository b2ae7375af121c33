# clrt_compile_in_batches(TARGET): TARGET's sources are compiled in batches of 16 (a unity
# build). Boost.Compute, CLI11, Catch2 and the JSON header are then parsed once a batch rather
# than once a file: the first build of clrt went from about 150 s to 64 s on two cores
# (docs/performance.md), and CI builds every test program twice (plain and sanitized). Names
# private to a source file must therefore be unique within its target.
function(clrt_compile_in_batches target)
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 16)
endfunction()
