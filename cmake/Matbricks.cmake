# matbricks_add_materials: compile materials (or exactly what a scene needs) into an
# engine-ready package at build time, with correct dependencies (docs/package.md "CMake").
#
#   matbricks_add_materials(TARGET tgt
#                           [SCENE file] [MATERIALS files...]
#                           [OUTPUT_DIR dir] [TARGETS spirv;glsl450;...]
#                           [NAMESPACE ns] [HEADER name.hpp] [OPTIMIZATION O0|O1|O2]
#                           [STAGES kernel;fragment] [COMPILE_ARGS args...])
#
# OPTIMIZATION: spirv-opt's level (`compile -O`; default: the scene's, else O2). -O0 compiles
# fastest, for iteration; docs/performance-compile.md "Levels" gives what each costs at run time.
# STAGES: the shader stages the package holds (`compile --stages`; default both): an engine that
# draws with fragment shaders only gives STAGES fragment and does not pay for the kernels.
# Needs MATBRICKS_EXECUTABLE (the matbricks command-line tool). The package is rebuilt when the
# scene, a material, the tool, or any file the last compile read changes: `compile --depfile`
# lists them (scene, glTF, materials, surface code, the shader library's manifest, slots,
# model and every included GLSL file) and add_custom_command(DEPFILE) reads it.
# `tgt` gets the package directory on its include path (#include "<HEADER>") and the compile
# definition MATBRICKS_PACKAGE_DIR="<dir>" to load the SPIR-V from.
function(matbricks_add_materials)
  cmake_parse_arguments(PARSE_ARGV 0 MB "" "TARGET;SCENE;OUTPUT_DIR;NAMESPACE;HEADER;OPTIMIZATION" "MATERIALS;TARGETS;STAGES;COMPILE_ARGS")
  if(MB_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "matbricks_add_materials: unknown arguments: ${MB_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT MB_TARGET OR NOT TARGET "${MB_TARGET}")
    message(FATAL_ERROR "matbricks_add_materials: TARGET must name an existing target (got '${MB_TARGET}')")
  endif()
  if(NOT MATBRICKS_EXECUTABLE)
    message(FATAL_ERROR "matbricks_add_materials: MATBRICKS_EXECUTABLE is not set; pass "
                        "-DMATBRICKS_EXECUTABLE=/path/to/matbricks (the matbricks command-line tool)")
  endif()
  if((MB_SCENE AND MB_MATERIALS) OR (NOT MB_SCENE AND NOT MB_MATERIALS))
    message(FATAL_ERROR "matbricks_add_materials: give either SCENE or MATERIALS, not both or neither")
  endif()
  if(NOT MB_OUTPUT_DIR)
    set(MB_OUTPUT_DIR "${CMAKE_CURRENT_BINARY_DIR}/matbricks/${MB_TARGET}")
  endif()
  if(NOT MB_NAMESPACE)
    set(MB_NAMESPACE matbricks_materials)
  endif()
  if(NOT MB_HEADER)
    set(MB_HEADER matbricks_materials.hpp)
  endif()
  cmake_path(ABSOLUTE_PATH MB_OUTPUT_DIR BASE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}" NORMALIZE)

  set(inputs "")
  if(MB_SCENE)
    cmake_path(ABSOLUTE_PATH MB_SCENE BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE)
    set(inputs "${MB_SCENE}")
    set(input_args --scene "${MB_SCENE}")
  else()
    foreach(m IN LISTS MB_MATERIALS)
      cmake_path(ABSOLUTE_PATH m BASE_DIRECTORY "${CMAKE_CURRENT_SOURCE_DIR}" NORMALIZE)
      list(APPEND inputs "${m}")
    endforeach()
    set(input_args ${inputs})
  endif()
  set(target_args "")
  if(MB_TARGETS)
    list(JOIN MB_TARGETS "," joined)
    set(target_args --targets "${joined}")
  endif()

  set(level_args "")
  if(MB_OPTIMIZATION)
    if(NOT MB_OPTIMIZATION MATCHES "^O[012]$")
      message(FATAL_ERROR "matbricks_add_materials: OPTIMIZATION must be O0, O1 or O2 (got '${MB_OPTIMIZATION}')")
    endif()
    set(level_args "-${MB_OPTIMIZATION}")
  endif()

  set(stage_args "")
  if(MB_STAGES)
    foreach(stage IN LISTS MB_STAGES)
      if(NOT stage MATCHES "^(kernel|fragment)$")
        message(FATAL_ERROR "matbricks_add_materials: STAGES takes kernel and fragment (got '${stage}')")
      endif()
    endforeach()
    list(JOIN MB_STAGES "," joined)
    set(stage_args --stages "${joined}")
  endif()

  set(depfile "${CMAKE_CURRENT_BINARY_DIR}/matbricks/${MB_TARGET}.d")
  set(outputs "${MB_OUTPUT_DIR}/manifest.json" "${MB_OUTPUT_DIR}/${MB_HEADER}")
  add_custom_command(
    OUTPUT ${outputs}
    COMMAND "${MATBRICKS_EXECUTABLE}" compile -q ${input_args} ${target_args} ${level_args} ${stage_args} -o "${MB_OUTPUT_DIR}"
            --header "${MB_HEADER}" --namespace "${MB_NAMESPACE}" --depfile "${depfile}" ${MB_COMPILE_ARGS}
    DEPENDS ${inputs} "${MATBRICKS_EXECUTABLE}"
    DEPFILE "${depfile}"
    COMMENT "matbricks: compiling the materials of ${MB_TARGET}"
    VERBATIM)
  add_custom_target(${MB_TARGET}_matbricks DEPENDS ${outputs})
  add_dependencies(${MB_TARGET} ${MB_TARGET}_matbricks)
  target_include_directories(${MB_TARGET} PRIVATE "${MB_OUTPUT_DIR}")
  target_compile_definitions(${MB_TARGET} PRIVATE MATBRICKS_PACKAGE_DIR="${MB_OUTPUT_DIR}")
endfunction()
