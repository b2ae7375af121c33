# Installs the build tree BUILD into PREFIX and checks that the programs, the plot script, the
# man page, the bash completion and the documentation are there, that the benchmarks are not, and that the installed programs run.
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
             share/doc/clrt/scene-format.md share/doc/clrt/images.md)
  if(NOT EXISTS ${PREFIX}/${file})
    message(FATAL_ERROR "cmake --install did not install ${file}")
  endif()
endforeach()
foreach(file bin/clrt-bench bin/clrt-embree-compare bin/clrt-png-settings)
  if(EXISTS ${PREFIX}/${file})
    message(FATAL_ERROR "cmake --install installed the benchmark ${file}")
  endif()
endforeach()
foreach(program clrt clrt-img clrt-experiment)
  execute_process(COMMAND ${PREFIX}/bin/${program} --version RESULT_VARIABLE status
                  OUTPUT_VARIABLE version)
  if(NOT status EQUAL 0 OR NOT version MATCHES "clrt [0-9]")
    message(FATAL_ERROR "the installed ${program} --version failed: ${version}")
  endif()
endforeach()
