# Kernel sources are compiled into the binary so that clrt runs from anywhere without an install
# step; the host resolves their #include lines itself (src/device/kernel_source.cpp).

set(_clrt_embed_script ${CMAKE_CURRENT_LIST_DIR}/embed_kernels_script.cmake)

function(clrt_embed_kernels target kernel_dir)
  file(GLOB_RECURSE _sources CONFIGURE_DEPENDS
       RELATIVE ${kernel_dir} ${kernel_dir}/*.cl ${kernel_dir}/*.h)
  list(SORT _sources)
  set(_out ${CMAKE_CURRENT_BINARY_DIR}/generated/embedded_kernels.cpp)
  set(_deps "")
  foreach(_s IN LISTS _sources)
    list(APPEND _deps ${kernel_dir}/${_s})
  endforeach()
  string(REPLACE ";" "|" _list "${_sources}")
  add_custom_command(
    OUTPUT ${_out}
    COMMAND ${CMAKE_COMMAND} -DKERNEL_DIR=${kernel_dir} -DFILES=${_list} -DOUT=${_out}
            -P ${_clrt_embed_script}
    DEPENDS ${_deps} ${_clrt_embed_script}
    COMMENT "Embedding OpenCL kernel sources"
    VERBATIM)
  add_library(${target} STATIC ${_out})
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/src)
endfunction()
