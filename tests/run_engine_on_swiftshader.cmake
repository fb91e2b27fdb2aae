# CTest driver (tests/CMakeLists.txt "engine_example_swiftshader"): runs the engine example the
# "engine_example" test built, with the Vulkan loader given SwiftShader's ICD only, and fails
# unless it exits 0, ran on SwiftShader (the example takes the first device and prints its
# name) and had the validation layer on (it counts every message and fails on one).
foreach(v ENGINE ICD)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_engine_on_swiftshader.cmake needs -D${v}=...")
  endif()
endforeach()
if(NOT EXISTS "${ICD}")
  message(FATAL_ERROR "${ICD} is missing: scripts/install-deps.sh installs Debian's `chromium`, which ships it")
endif()
get_filename_component(dir "${ENGINE}" DIRECTORY)
execute_process(COMMAND "${CMAKE_COMMAND}" -E env "VK_ICD_FILENAMES=${ICD}" "${ENGINE}" WORKING_DIRECTORY "${dir}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "engine example on SwiftShader failed (${rc})")
endif()
if(NOT out MATCHES "device: SwiftShader Device \\(Subzero\\)\n")
  message(FATAL_ERROR "engine example did not run on SwiftShader Device (Subzero)")
endif()
if(NOT out MATCHES "validation layer: on\n")
  message(FATAL_ERROR "engine example ran without the validation layer")
endif()
