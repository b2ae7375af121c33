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
