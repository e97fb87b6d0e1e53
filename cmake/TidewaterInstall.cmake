# Installs Tidewater as a CMake package: find_package(Tidewater [COMPONENTS core bake
# render calibration]) gives Tidewater::core always, Tidewater::bake where GMP and libpng
# are, Tidewater::render where Vulkan is found and Tidewater::calibration where Ceres and
# netCDF are. The exported files hold no path of
# the build machine: the dependencies are found again on the host machine.
include(CMakePackageConfigHelpers)

set(TIDEWATER_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Tidewater)

function(tidewater_install_component target component)
  install(TARGETS ${target} EXPORT Tidewater${component}Targets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  install(EXPORT Tidewater${component}Targets NAMESPACE Tidewater:: DESTINATION ${TIDEWATER_CMAKE_DIR})
  export(EXPORT Tidewater${component}Targets NAMESPACE Tidewater:: FILE ${PROJECT_BINARY_DIR}/Tidewater${component}Targets.cmake)
endfunction()

tidewater_install_component(tidewater_core Core)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/runtime/core/include/tidewater
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
install(FILES ${PROJECT_BINARY_DIR}/runtime/core/include/tidewater/version.hpp
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/tidewater)
tidewater_install_component(tidewater_bake Bake)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/runtime/bake/include/tidewater
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
if(TARGET tidewater_render)
  tidewater_install_component(tidewater_render Render)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/runtime/render/include/tidewater
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
endif()
if(TARGET tidewater_calibration)
  tidewater_install_component(tidewater_calibration Calibration)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/calibration/include/tidewater
    DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} FILES_MATCHING PATTERN "*.hpp")
endif()
# The bundled presets and scenes as files (the library has them built in by name).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/presets ${PROJECT_SOURCE_DIR}/examples/scenes
  DESTINATION ${CMAKE_INSTALL_DATADIR}/tidewater FILES_MATCHING PATTERN "*.json")

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/TidewaterConfig.cmake.in
  ${PROJECT_BINARY_DIR}/TidewaterConfig.cmake INSTALL_DESTINATION ${TIDEWATER_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/TidewaterConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/TidewaterConfig.cmake ${PROJECT_BINARY_DIR}/TidewaterConfigVersion.cmake
  DESTINATION ${TIDEWATER_CMAKE_DIR})
