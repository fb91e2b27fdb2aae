# CTest driver "install" (docs/install.md): installs the freshly built matbricks to a scratch
# prefix, checks the layout, then — with the source tree hidden where the system allows it (a
# private mount namespace with an empty tmpfs over it) — builds examples/engine from a copy
# outside the source tree against the installed CMake package only, runs it, and checks that
# the installed CLI reads the installed shader library. Finally `cpack` builds the .deb and
# its contents are listed.
foreach(v BUILD_DIR SOURCE_DIR SCRATCH GENERATOR)
  if(NOT DEFINED ${v})
    message(FATAL_ERROR "run_install_test.cmake needs -D${v}=...")
  endif()
endforeach()

function(check_ok what rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "install test: ${what} failed (${rc})")
  endif()
endfunction()

file(REMOVE_RECURSE "${SCRATCH}")
set(prefix "${SCRATCH}/prefix")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}" OUTPUT_QUIET RESULT_VARIABLE rc)
check_ok("cmake --install" "${rc}")
foreach(f bin/matbricks share/matbricks/shaderlib/manifest.json share/matbricks/materials/ue4_metal.json
          lib/cmake/matbricks/matbricksConfig.cmake lib/cmake/matbricks/Matbricks.cmake share/doc/matbricks/README.md
          share/doc/matbricks/install.md)
  if(NOT EXISTS "${prefix}/${f}")
    message(FATAL_ERROR "install test: ${prefix}/${f} was not installed")
  endif()
endforeach()

# The consumer: a copy of examples/engine outside the source tree, the installed materials.
file(COPY "${SOURCE_DIR}/examples/engine/" DESTINATION "${SCRATCH}/engine-src")
set(data "${prefix}/share/matbricks")
set(steps "${SCRATCH}/steps.sh")
file(WRITE "${steps}" "set -e
'${CMAKE_COMMAND}' -S '${SCRATCH}/engine-src' -B '${SCRATCH}/engine-build' -G '${GENERATOR}' \\
  -DCMAKE_PREFIX_PATH='${prefix}' '-DMATBRICKS_COMPILE_ARGS=--cache-dir=${SCRATCH}/cache'
'${CMAKE_COMMAND}' --build '${SCRATCH}/engine-build' -j2
'${SCRATCH}/engine-build/engine_example'
'${prefix}/bin/matbricks' compile '${data}/materials/ue4_metal.json' -o '${SCRATCH}/pkg' -q \\
  --cache-dir '${SCRATCH}/cache' --depfile '${SCRATCH}/pkg.d'
")
# Hide the source tree (and the build tree inside it) behind an empty tmpfs in a private mount
# namespace; where unshare or mount is not allowed, run the same steps with it visible.
execute_process(COMMAND unshare --mount sh -c "mount -t tmpfs tmpfs '${SOURCE_DIR}' && test ! -e '${SOURCE_DIR}/CMakeLists.txt' && sh '${steps}'"
                RESULT_VARIABLE rc)
if(rc EQUAL 0)
  message("install test: the engine built and ran with the source tree hidden")
else()
  message(WARNING "install test: could not hide the source tree (unshare/mount: ${rc}); running with it visible")
  execute_process(COMMAND sh "${steps}" RESULT_VARIABLE rc)
  check_ok("the engine build against the installed package" "${rc}")
endif()

file(READ "${SCRATCH}/pkg.d" deps)
string(FIND "${deps}" "${data}/shaderlib/manifest.json" at)
if(at EQUAL -1)
  message(FATAL_ERROR "install test: the installed matbricks did not read the installed shader library:\n${deps}")
endif()
string(FIND "${deps}" "${SOURCE_DIR}/shaderlib" at)
if(NOT at EQUAL -1)
  message(FATAL_ERROR "install test: the installed matbricks read the source tree's shader library:\n${deps}")
endif()

# The .deb: built by CPack from the same install rules.
execute_process(COMMAND "${CMAKE_CPACK_COMMAND}" -G DEB -B "${SCRATCH}/deb" --config "${BUILD_DIR}/CPackConfig.cmake"
                OUTPUT_QUIET RESULT_VARIABLE rc)
check_ok("cpack -G DEB" "${rc}")
file(GLOB debs "${SCRATCH}/deb/*.deb")
list(LENGTH debs n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "install test: cpack made ${n} .deb files")
endif()
execute_process(COMMAND dpkg-deb --contents ${debs} OUTPUT_VARIABLE listing RESULT_VARIABLE rc)
check_ok("dpkg-deb --contents" "${rc}")
foreach(f ./usr/bin/matbricks ./usr/share/matbricks/shaderlib/manifest.json ./usr/lib/cmake/matbricks/matbricksConfig.cmake)
  string(FIND "${listing}" "${f}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "install test: ${debs} lacks ${f}")
  endif()
endforeach()
file(REMOVE_RECURSE "${SCRATCH}")
