# CTest driver for examples/engine (tests/CMakeLists.txt "engine_example"): configure, build
# and run the example as an outside project would, with the freshly built matbricks, then
# check the build's dependencies (a no-op rebuild compiles nothing; editing a file that only
# the depfile names rebuilds the package). The compile cache lives in the example's build
# directory, so the test never touches ~/.cache.
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

# The materials, copied into the build tree so that the test may touch them: ue4_metal as
# JSON, filament_plastic in the macro form with its roughness in an #included file, which only
# the depfile names (matbricks_add_materials' DEPENDS lists the top-level files).
set(materials "${BINARY_DIR}/materials")
file(MAKE_DIRECTORY "${materials}")
file(COPY_FILE "${MATBRICKS_SOURCE_DIR}/materials/ue4_metal.json" "${materials}/ue4_metal.json")
file(READ "${MATBRICKS_SOURCE_DIR}/materials/filament_plastic.mat" plastic)
string(REGEX MATCH "#define PARAM_roughness[^\n]*\n" roughness "${plastic}")
if(NOT roughness)
  message(FATAL_ERROR "engine example: materials/filament_plastic.mat has no PARAM_roughness line")
endif()
string(REPLACE "${roughness}" "#include \"plastic_roughness.mat\"\n" plastic "${plastic}")
file(WRITE "${materials}/filament_plastic.mat" "${plastic}")
file(WRITE "${materials}/plastic_roughness.mat" "${roughness}")

function(build_step what out_var)
  execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BINARY_DIR}" -j2 WORKING_DIRECTORY "${BINARY_DIR}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message("${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "engine example: ${what} failed (${rc})")
  endif()
  set(${out_var} "${out}" PARENT_SCOPE)
endfunction()

run_step(configure "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${BINARY_DIR}" -G "${GENERATOR}"
         -DMATBRICKS_EXECUTABLE=${MATBRICKS_EXECUTABLE} -DMATBRICKS_SOURCE_DIR=${MATBRICKS_SOURCE_DIR}
         "-DMATBRICKS_ENGINE_MATERIALS=${materials}/ue4_metal.json\;${materials}/filament_plastic.mat"
         "-DMATBRICKS_COMPILE_ARGS=--cache-dir=${BINARY_DIR}/matbricks-cache")
build_step(build out)
run_step(run "${BINARY_DIR}/engine_example")

# Dependencies: nothing changed, nothing compiles; a file only the depfile lists changed, the
# package is rebuilt.
set(compiling "matbricks: compiling the materials of engine_example")
build_step("no-op rebuild" out)
if(out MATCHES "${compiling}")
  message(FATAL_ERROR "engine example: a no-op rebuild ran matbricks again")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" -E sleep 1)
file(TOUCH "${materials}/plastic_roughness.mat")
build_step("rebuild after editing an #included material file" out)
if(NOT out MATCHES "${compiling}")
  message(FATAL_ERROR "engine example: editing ${materials}/plastic_roughness.mat did not rebuild the package")
endif()
