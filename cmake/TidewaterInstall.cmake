# Installs Tidewater as a CMake package: find_package(Tidewater) gives
# Tidewater::core (and, as they land, Tidewater::render and Tidewater::calibration).
include(CMakePackageConfigHelpers)

set(TIDEWATER_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Tidewater)

set(tidewater_installed_targets tidewater_core)
set(TIDEWATER_CONFIG_DEPENDENCIES "")
if(TARGET tidewater_render)
  list(APPEND tidewater_installed_targets tidewater_render)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/runtime/render/include/tidewater
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
  set(TIDEWATER_CONFIG_DEPENDENCIES "find_dependency(Vulkan)")
endif()

install(TARGETS ${tidewater_installed_targets} EXPORT TidewaterTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/runtime/core/include/tidewater
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/runtime/core/include/tidewater/version.hpp
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tidewater)

install(EXPORT TidewaterTargets NAMESPACE Tidewater:: DESTINATION ${TIDEWATER_CMAKE_DIR})
export(EXPORT TidewaterTargets NAMESPACE Tidewater:: FILE ${PROJECT_BINARY_DIR}/TidewaterTargets.cmake)

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/TidewaterConfig.cmake.in
  ${PROJECT_BINARY_DIR}/TidewaterConfig.cmake INSTALL_DESTINATION ${TIDEWATER_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/TidewaterConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/TidewaterConfig.cmake ${PROJECT_BINARY_DIR}/TidewaterConfigVersion.cmake
  DESTINATION ${TIDEWATER_CMAKE_DIR})
