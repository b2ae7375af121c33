# `cmake --install build [--prefix DIR]`: clrt, its tools, the plot script they run and the
# documentation. The kernels are compiled into the executables, so nothing else is needed at
# run time. The benchmarks (tools/bench/) stay in the build tree: they measure clrt for its
# developers and are run from a clone, beside the scenes and scripts they go with.
include(GNUInstallDirs)

set(clrt_installed_programs clrt clrt-img clrt-experiment clrt-make-scenes)
if(TARGET clrt-mpi)
  list(APPEND clrt_installed_programs clrt-mpi)
endif()
install(TARGETS ${clrt_installed_programs} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(PROGRAMS tools/experiment/plot_experiment.py DESTINATION ${CMAKE_INSTALL_DATADIR}/clrt)
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} FILES_MATCHING PATTERN "*.md")
