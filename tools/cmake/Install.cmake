# `cmake --install build [--prefix DIR]`: clrt, its tools, the plot script they run and the
# documentation. The kernels are compiled into the executables, so nothing else is needed at
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
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} FILES_MATCHING PATTERN "*.md")
