# Kernel sources are compiled into the binary so that clrt runs from anywhere without an install
# step; the host resolves their #include lines itself (src/device/kernel_source.cpp).

set(_clrt_embed_script ${CMAKE_CURRENT_LIST_DIR}/embed_kernels_script.cmake)

# Embeds every file of `kernel_dir` and of `generated_dir` (the kind lists of KindLists.cmake),
# each under its path relative to its folder.
function(clrt_embed_kernels target kernel_dir generated_dir)
  file(GLOB_RECURSE _sources CONFIGURE_DEPENDS
       RELATIVE ${kernel_dir} ${kernel_dir}/*.cl ${kernel_dir}/*.h)
  file(GLOB_RECURSE _generated RELATIVE ${generated_dir} ${generated_dir}/*.h)
  list(SORT _sources)
  list(SORT _generated)
  set(_out ${CMAKE_CURRENT_BINARY_DIR}/generated/embedded_kernels.cpp)
  set(_deps "")
  foreach(_s IN LISTS _sources)
    list(APPEND _deps ${kernel_dir}/${_s})
  endforeach()
  foreach(_s IN LISTS _generated)
    list(APPEND _deps ${generated_dir}/${_s})
  endforeach()
  string(REPLACE ";" "|" _list "${_sources}")
  string(REPLACE ";" "|" _generated_list "${_generated}")
  add_custom_command(
    OUTPUT ${_out}
    COMMAND ${CMAKE_COMMAND} -DKERNEL_DIR=${kernel_dir} -DFILES=${_list}
            -DGENERATED_DIR=${generated_dir} -DGENERATED=${_generated_list} -DOUT=${_out}
            -P ${_clrt_embed_script}
    DEPENDS ${_deps} ${_clrt_embed_script}
    COMMENT "Embedding OpenCL kernel sources"
    VERBATIM)
  add_library(${target} STATIC ${_out})
  target_include_directories(${target} PRIVATE ${PROJECT_SOURCE_DIR}/src)
endfunction()
