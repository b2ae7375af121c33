# cmake -DSOURCE=DIR -DBINARY=DIR -DCXX=COMPILER -DTARGETS=A,B,... -P build_sanitized.cmake:
# configures BINARY as a sanitized tree of SOURCE and builds the targets named (with what they
# depend on). Run by the CTest test sanitized:build. Debug keeps assert() on;
# tools/cmake/Sanitizers.cmake sets the optimisation. The tree is configured every time (seconds
# when nothing changed): a tree whose configure was cut short has a cache but no build files,
# and must not be taken for a finished one.
execute_process(
  COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -DCMAKE_BUILD_TYPE=Debug
          -DCMAKE_CXX_COMPILER=${CXX} -DCLRT_SANITIZE=ON
  RESULT_VARIABLE result)
if(result)
  message(FATAL_ERROR "configuring the sanitized tree ${BINARY} failed")
endif()
cmake_host_system_information(RESULT cores QUERY NUMBER_OF_LOGICAL_CORES)
string(REPLACE "," ";" targets "${TARGETS}")
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY} -j${cores} --target ${targets}
                RESULT_VARIABLE result)
if(result)
  message(FATAL_ERROR "building the sanitized tree ${BINARY} failed")
endif()
