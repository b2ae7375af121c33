# A kind of light is its device file in kernels/render/lights/ and its row of the host's table
# (src/scene/light_kinds.cpp): the list of kinds that the device dispatches over, and that numbers
# them for both sides, is written here from the files of that folder, so adding a kind edits no
# list. A lobe is its file in kernels/render/lobes/, included from the list written here, and its
# row of CLRT_LOBES (kernels/render/lobes.h), which orders the lobes and is checked against it. Written at configure time (the glob re-runs when a file is added or removed) into
# ${CLRT_GENERATED_KERNELS}, which the build embeds beside kernels/ and the host includes.

set(CLRT_GENERATED_KERNELS ${PROJECT_BINARY_DIR}/generated_kernels)

# Writes shared/NAME_kinds.h, X-list CLRT_PREFIX_KINDS(X) with one X(UPPER, lower) per file of
# kernels/FOLDER/ in sorted order (host and device), and render/NAME_files.h, which includes every
# one of those files (device only).
function(clrt_kind_list name folder prefix)
  file(GLOB _files CONFIGURE_DEPENDS RELATIVE ${PROJECT_SOURCE_DIR}/kernels/${folder}
       ${PROJECT_SOURCE_DIR}/kernels/${folder}/*.h)
  list(SORT _files)
  set(_rows "")
  set(_includes "")
  foreach(_file IN LISTS _files)
    string(REGEX REPLACE "\\.h$" "" _lower ${_file})
    string(TOUPPER ${_lower} _upper)
    string(APPEND _rows " X(${_upper}, ${_lower})")
    string(APPEND _includes "#include \"${folder}/${_file}\"\n")
  endforeach()
  string(TOUPPER ${name} _guard)
  file(CONFIGURE OUTPUT ${CLRT_GENERATED_KERNELS}/shared/${name}_kinds.h @ONLY CONTENT
"/* Written by tools/cmake/KindLists.cmake from the files of kernels/${folder}/: one row per
 * file, X(UPPER, lower), in the order of the files' names. */
#ifndef CLRT_SHARED_${_guard}_KINDS_H
#define CLRT_SHARED_${_guard}_KINDS_H
#define ${prefix}_KINDS(X)${_rows}
#endif
")
  file(CONFIGURE OUTPUT ${CLRT_GENERATED_KERNELS}/render/${name}_files.h @ONLY CONTENT
"/* Written by tools/cmake/KindLists.cmake: every file of kernels/${folder}/. */
${_includes}")
endfunction()
