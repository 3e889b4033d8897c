# `cmake --install`: the headers, and the package configuration that
# find_package(Mesh_untangling) reads (relocatable: the prefix may be moved).
# Component Mesh_untangling_Development holds them; the command-line tool,
# when built, is in Mesh_untangling_Runtime.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/CGAL
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT Mesh_untangling_Development)

# Header-only: the configuration is architecture-independent, under share/.
set(MESH_UNTANGLING_CONFIG_DESTINATION ${CMAKE_INSTALL_DATADIR}/cmake/Mesh_untangling)
configure_package_config_file(${CMAKE_CURRENT_SOURCE_DIR}/cmake/Mesh_untanglingConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/Mesh_untanglingConfig.cmake
                              INSTALL_DESTINATION ${MESH_UNTANGLING_CONFIG_DESTINATION}
                              PATH_VARS CMAKE_INSTALL_INCLUDEDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/Mesh_untanglingConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION}
                                 COMPATIBILITY SameMajorVersion
                                 ARCH_INDEPENDENT)
install(FILES ${PROJECT_BINARY_DIR}/Mesh_untanglingConfig.cmake
              ${PROJECT_BINARY_DIR}/Mesh_untanglingConfigVersion.cmake
              ${CMAKE_CURRENT_SOURCE_DIR}/cmake/Mesh_untanglingDependencies.cmake
        DESTINATION ${MESH_UNTANGLING_CONFIG_DESTINATION}
        COMPONENT Mesh_untangling_Development)

if(TARGET untangle_mesh_cli)
  install(TARGETS untangle_mesh_cli RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
          COMPONENT Mesh_untangling_Runtime)
endif()
