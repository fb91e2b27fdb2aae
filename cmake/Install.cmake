# cmake --install and CPack (docs/install.md): the CLI, the shader library and example
# materials it finds relative to itself (compiler/core/data_dir.hpp), the CMake package
# (find_package(matbricks CONFIG) -> matbricks::matbricks, matbricks_add_materials) and the
# docs, under one prefix; `cpack` builds a .deb of the same tree.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(TARGETS matbricks RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The library at run time is its manifest, slot/model JSON and GLSL; the C++ references are
# compiled into the program.
install(DIRECTORY shaderlib/ DESTINATION ${CMAKE_INSTALL_DATADIR}/matbricks/shaderlib
        FILES_MATCHING PATTERN "*.json" PATTERN "*.glsl" PATTERN "*.vert")
install(DIRECTORY materials/ DESTINATION ${CMAKE_INSTALL_DATADIR}/matbricks/materials)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

set(MB_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/matbricks)
set(MB_DATA_DIR ${CMAKE_INSTALL_DATADIR}/matbricks)
configure_package_config_file(cmake/matbricksConfig.cmake.in ${CMAKE_BINARY_DIR}/matbricksConfig.cmake
                              INSTALL_DESTINATION ${MB_CMAKE_DIR} PATH_VARS CMAKE_INSTALL_BINDIR MB_DATA_DIR)
write_basic_package_version_file(${CMAKE_BINARY_DIR}/matbricksConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/matbricksConfig.cmake ${CMAKE_BINARY_DIR}/matbricksConfigVersion.cmake
              cmake/Matbricks.cmake
        DESTINATION ${MB_CMAKE_DIR})

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME matbricks)
set(CPACK_PACKAGE_VENDOR matbricks)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "PBR brick library, material compiler and validator")
set(CPACK_PACKAGE_INSTALL_DIRECTORY matbricks)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "matbricks developers")
set(CPACK_DEBIAN_PACKAGE_SECTION devel)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
# Shared-library dependencies from dpkg-shlibdeps (libvulkan1, libspirv-cross-c-shared0, ...);
# a Vulkan driver to validate on is recommended, not required (compile needs none).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "mesa-vulkan-drivers")
include(CPack)
