# Install rules that are not per target (simp_add_library / simp_add_app install their targets):
# the CMake package of the libraries, the experiment configs and the documents (doc/plugin.md
# "Installing"). Consumers: find_package(simp CONFIG REQUIRED), then link simp::<lib>.
include(CMakePackageConfigHelpers)

set(SIMP_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/simp)

install(EXPORT simpTargets NAMESPACE simp:: DESTINATION ${SIMP_INSTALL_CMAKEDIR} FILE simpTargets.cmake)

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/simpConfig.cmake.in
  ${CMAKE_BINARY_DIR}/simpConfig.cmake
  INSTALL_DESTINATION ${SIMP_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_INCLUDEDIR CMAKE_INSTALL_LIBDIR CMAKE_INSTALL_DATADIR)
# 0.x: a consumer asking for 0.1 accepts only 0.1.z (the ABI may change with every minor version).
write_basic_package_version_file(${CMAKE_BINARY_DIR}/simpConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/simpConfig.cmake ${CMAKE_BINARY_DIR}/simpConfigVersion.cmake
  DESTINATION ${SIMP_INSTALL_CMAKEDIR})

install(DIRECTORY ${CMAKE_SOURCE_DIR}/config_ini/ DESTINATION ${CMAKE_INSTALL_DATADIR}/simp/config_ini)
install(DIRECTORY ${CMAKE_SOURCE_DIR}/doc/ DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(FILES ${CMAKE_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})


# No pkg-config file: MRPT 2.5 ships none for its libraries, so a simp.pc could not name its
# dependencies; use the CMake package.
