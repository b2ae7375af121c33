# `cmake --install build [--prefix DIR]`: clrt, its tools, the plot script they run, the example
# scenes and the documentation. The kernels are compiled into the executables, so nothing else is needed at
# run time. The benchmarks (tools/bench/) stay in the build tree: they measure clrt for its
# developers and are run from a clone, beside the scenes and scripts they go with.
include(GNUInstallDirs)

set(clrt_installed_programs clrt clrt-img clrt-experiment clrt-make-scenes)
foreach(optional clrt-mpi clrt-view)
  if(TARGET ${optional})
    list(APPEND clrt_installed_programs ${optional})
  endif()
endforeach()
install(TARGETS ${clrt_installed_programs} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# Each program's man page and bash completion, written by the program itself from the parser it
# runs (src/cli/docs/cli_docs_option.hpp), into share/ of the build tree as they are installed.
set(clrt_cli_docs "")
foreach(program IN LISTS clrt_installed_programs)
  set(page ${PROJECT_BINARY_DIR}/share/man/man1/${program}.1)
  set(completion ${PROJECT_BINARY_DIR}/share/bash-completion/completions/${program})
  add_custom_command(OUTPUT ${page} ${completion}
    COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/share/man/man1
            ${PROJECT_BINARY_DIR}/share/bash-completion/completions
    COMMAND ${program} --write-man-page ${page}
    COMMAND ${program} --write-bash-completion ${completion}
    DEPENDS ${program}
    COMMENT "Writing ${program}'s man page and bash completion")
  list(APPEND clrt_cli_docs ${page} ${completion})
  install(FILES ${page} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  install(FILES ${completion} DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)
endforeach()
add_custom_target(clrt_cli_docs ALL DEPENDS ${clrt_cli_docs})
install(PROGRAMS tools/experiment/plot_experiment.py DESTINATION ${CMAKE_INSTALL_DATADIR}/clrt)
# The scenes of scenes/ (without the large ones), to try clrt on: share/clrt/scenes.
install(DIRECTORY scenes/ DESTINATION ${CMAKE_INSTALL_DATADIR}/clrt/scenes PATTERN large EXCLUDE)
# The documentation as the source tree lays it out (README.md beside docs/), so that its links
# between pages hold; a link to a file not installed is rewritten into that file's path in the
# source tree (tools/cmake/install_docs_links.cmake).
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
install(CODE "set(DOC \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_DOCDIR}\")
include(\"${PROJECT_SOURCE_DIR}/tools/cmake/install_docs_links.cmake\")")
