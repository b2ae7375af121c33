# Installs the build tree BUILD into PREFIX and checks that the programs, the plot script, the
# man page, the bash completion, the example scenes and the documentation are there, that every
# relative link of the installed documentation leads to an installed file, that the benchmarks
# are not there, and that the installed programs run (clrt on an installed scene).
# From an empty PREFIX: a former install's files would pass for this one's.
file(REMOVE_RECURSE ${PREFIX})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX}
                RESULT_VARIABLE status OUTPUT_QUIET)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${status})")
endif()
foreach(file bin/clrt bin/clrt-img bin/clrt-experiment bin/clrt-make-scenes
             share/clrt/plot_experiment.py share/doc/clrt/README.md share/man/man1/clrt.1
             share/bash-completion/completions/clrt
             share/doc/clrt/docs/scene-format.md share/doc/clrt/docs/images.md
             share/doc/clrt/docs/cli.md share/clrt/scenes/reflect.ray share/clrt/scenes/meshes/icosphere.obj)
  if(NOT EXISTS ${PREFIX}/${file})
    message(FATAL_ERROR "cmake --install did not install ${file}")
  endif()
endforeach()
foreach(file bin/clrt-bench bin/clrt-embree-compare bin/clrt-png-settings)
  if(EXISTS ${PREFIX}/${file})
    message(FATAL_ERROR "cmake --install installed the benchmark ${file}")
  endif()
endforeach()
# Every installed program has its man page and completion, and its --help names a page that is
# installed, where this install put it (the docs beside the program, whatever the prefix).
file(GLOB programs RELATIVE ${PREFIX}/bin "${PREFIX}/bin/clrt*")
foreach(program IN LISTS programs)
  foreach(file share/man/man1/${program}.1 share/bash-completion/completions/${program})
    if(NOT EXISTS ${PREFIX}/${file})
      message(FATAL_ERROR "cmake --install installed ${program} without ${file}")
    endif()
  endforeach()
  execute_process(COMMAND ${PREFIX}/bin/${program} --help RESULT_VARIABLE status OUTPUT_VARIABLE help)
  if(NOT help MATCHES ", and ([^\n]*)/(docs/[a-z-]+\\.md)\n")
    message(FATAL_ERROR "the installed ${program} --help names no manual page: ${help}")
  endif()
  get_filename_component(installed_docs ${PREFIX}/share/doc/clrt REALPATH)
  if(NOT CMAKE_MATCH_1 STREQUAL installed_docs)
    message(FATAL_ERROR "the installed ${program} --help names ${CMAKE_MATCH_1}, not ${installed_docs}")
  endif()
  set(CMAKE_MATCH_1 ${CMAKE_MATCH_2})
  if(NOT EXISTS ${PREFIX}/share/doc/clrt/${CMAKE_MATCH_1})
    message(FATAL_ERROR "the installed ${program} --help names ${CMAKE_MATCH_1}, which is not installed")
  endif()
endforeach()
foreach(program clrt clrt-img clrt-experiment)
  execute_process(COMMAND ${PREFIX}/bin/${program} --version RESULT_VARIABLE status
                  OUTPUT_VARIABLE version)
  if(NOT status EQUAL 0 OR NOT version MATCHES "clrt [0-9]")
    message(FATAL_ERROR "the installed ${program} --version failed: ${version}")
  endif()
endforeach()

# Every relative link of the installed pages, to a file that is there.
file(GLOB_RECURSE pages "${PREFIX}/share/doc/clrt/*.md")
set(broken "")
foreach(page IN LISTS pages)
  file(READ "${page}" text)
  get_filename_component(folder "${page}" DIRECTORY)
  string(REGEX MATCHALL "\\]\\([^) \n]+\\)" links "${text}")
  foreach(link IN LISTS links)
    string(REGEX REPLACE "^\\]\\(([^)#]*).*$" "\\1" path "${link}")
    if(path STREQUAL "" OR path MATCHES "^[a-zA-Z]+:")
      continue()
    endif()
    get_filename_component(resolved "${path}" ABSOLUTE BASE_DIR "${folder}")
    if(NOT EXISTS "${resolved}")
      file(RELATIVE_PATH where "${PREFIX}" "${page}")
      string(APPEND broken "\n  ${where}: ${path}")
    endif()
  endforeach()
endforeach()
if(broken)
  message(FATAL_ERROR "installed documentation links to files that are not installed:${broken}")
endif()
list(LENGTH pages page_count)
if(page_count LESS 14)
  message(FATAL_ERROR "only ${page_count} pages of documentation were installed")
endif()

# The installed clrt renders an installed example scene, its meshes found beside it.
execute_process(COMMAND ${PREFIX}/bin/clrt ${PREFIX}/share/clrt/scenes/mesh.ray --resolution 16x8 -q
                        -o ${PREFIX}/mesh.png
                RESULT_VARIABLE status ERROR_VARIABLE error)
if(NOT status EQUAL 0 OR NOT EXISTS ${PREFIX}/mesh.png)
  message(FATAL_ERROR "the installed clrt could not render the installed mesh.ray: ${error}")
endif()
