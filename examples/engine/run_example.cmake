# CTest driver for examples/engine (tests/CMakeLists.txt "engine_example"): configure, build
# and run the example as an outside project would, with the freshly built matbricks. The
# compile cache lives in the example's build directory, so the test never touches ~/.cache.
foreach(v SOURCE_DIR BINARY_DIR MATBRICKS_EXECUTABLE MATBRICKS_SOURCE_DIR GENERATOR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_example.cmake needs -D${v}=...")
  endif()
endforeach()

function(run_step what)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY "${BINARY_DIR}" RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "engine example: ${what} failed (${rc})")
  endif()
endfunction()

file(MAKE_DIRECTORY "${BINARY_DIR}")
run_step(configure "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${BINARY_DIR}" -G "${GENERATOR}"
         -DMATBRICKS_EXECUTABLE=${MATBRICKS_EXECUTABLE} -DMATBRICKS_SOURCE_DIR=${MATBRICKS_SOURCE_DIR}
         "-DMATBRICKS_COMPILE_ARGS=--cache-dir=${BINARY_DIR}/matbricks-cache")
run_step(build "${CMAKE_COMMAND}" --build "${BINARY_DIR}" -j2)
run_step(run "${BINARY_DIR}/engine_example")
