# CTest layers_back_edge_fails: the include checker (cmake/CheckLayers.cmake) passes on
# compiler/ and shaderlib/ and fails, naming the file, line, column and edge, on a scratch copy
# with one back edge added (compile/ including write/, the edge the layers once had; a brick's
# reference including library/, as the references once did for ValueType), and on a graph
# with a cycle. Run with -DLAYERS=<build>/mb_layers.cmake -DSOURCE_DIR=<compiler/>
# -DDATA_DIR=<shaderlib/> -DSCRATCH=<a directory it may replace>.
set(checker ${CMAKE_CURRENT_LIST_DIR}/../cmake/CheckLayers.cmake)

function(run_checker layers source result_var output_var)
  execute_process(COMMAND ${CMAKE_COMMAND} -DLAYERS=${layers} -DSOURCE_DIR=${source} ${ARGN} -P ${checker}
                  RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(${result_var} ${result} PARENT_SCOPE)
  set(${output_var} "${out}${err}" PARENT_SCOPE)
endfunction()

# Appends `include` to `victim` as its last line; `line_var`: that line's number.
function(append_include victim include line_var)
  file(READ ${victim} text)
  string(REGEX MATCHALL "\n" newlines "${text}")
  list(LENGTH newlines lines)
  math(EXPR line "${lines} + 1")
  file(APPEND ${victim} "#include \"${include}\"\n")
  set(${line_var} ${line} PARENT_SCOPE)
endfunction()

run_checker(${LAYERS} ${SOURCE_DIR} result output -DDATA_DIR=${DATA_DIR})
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the checker fails on the real tree:\n${output}")
endif()

file(REMOVE_RECURSE ${SCRATCH})
file(COPY ${SOURCE_DIR}/ DESTINATION ${SCRATCH}/compiler)
append_include(${SCRATCH}/compiler/compile/shader_cache.cpp write/package_writer.hpp line)
run_checker(${LAYERS} ${SCRATCH}/compiler result output)
if(result EQUAL 0)
  message(FATAL_ERROR "the checker accepts compile/ including write/:\n${output}")
endif()
set(expected "compile/shader_cache.cpp:${line}:11: error: compile/ may not include write/: mb_compile does not link mb_write")
string(FIND "${output}" "${expected}" at)
if(at LESS 0)
  message(FATAL_ERROR "expected '${expected}' in the checker's output:\n${output}")
endif()

# The brick library below every layer but core/: a reference including library/.
file(COPY ${DATA_DIR}/ DESTINATION ${SCRATCH}/shaderlib)
append_include(${SCRATCH}/shaderlib/common/reference.hpp library/shader_library.hpp line)
run_checker(${LAYERS} ${SOURCE_DIR} result output -DDATA_DIR=${SCRATCH}/shaderlib)
set(expected "shaderlib/common/reference.hpp:${line}:11: error: the brick library may not include library/")
string(FIND "${output}" "${expected}" at)
if(result EQUAL 0 OR at LESS 0)
  message(FATAL_ERROR "expected '${expected}' in the checker's output:\n${output}")
endif()

# A cycle in the graph itself (write -> compile -> write), as a target_link_libraries added
# outside mb_layer would make it.
file(READ ${LAYERS} graph)
string(REGEX REPLACE "set\\(MB_LAYER_DEPS_compile ([^)]*)\\)" "set(MB_LAYER_DEPS_compile \\1 write)" graph "${graph}")
file(WRITE ${SCRATCH}/mb_layers_cycle.cmake "${graph}")
run_checker(${SCRATCH}/mb_layers_cycle.cmake ${SOURCE_DIR} result output)
string(FIND "${output}" "error: the layer targets form a cycle: compile -> write -> compile" at)
if(result EQUAL 0 OR at LESS 0)
  message(FATAL_ERROR "the checker does not report the cycle compile -> write -> compile:\n${output}")
endif()
file(REMOVE_RECURSE ${SCRATCH})
