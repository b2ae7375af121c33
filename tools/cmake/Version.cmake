# clrt_version library: clrt_version_string() = "clrt X.Y.Z (commit HASH[-dirty])". The commit is
# read at every build (not only at configure time), so an experiment's record names the code
# that really ran; the file is rewritten only when the text changes, so nothing else rebuilds.

set(_clrt_version_script ${CMAKE_CURRENT_LIST_DIR}/version_script.cmake)

function(clrt_add_version_library target)
  set(_out ${CMAKE_CURRENT_BINARY_DIR}/generated/clrt_version.cpp)
  add_custom_target(${target}_refresh
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DVERSION=${PROJECT_VERSION}
            -DOUT=${_out} -P ${_clrt_version_script}
    BYPRODUCTS ${_out}
    COMMENT "Reading the commit for clrt --version"
    VERBATIM)
  add_library(${target} STATIC ${_out})
  add_dependencies(${target} ${target}_refresh)
endfunction()
