# Builds examples/consumer against Tidewater in one of two ways and runs it.
#   MODE=find_package      install the build tree to a prefix, then find_package(Tidewater)
#   MODE=add_subdirectory  add Tidewater's source tree with add_subdirectory
#   MODE=embed_minimal     install, move the prefix, build and run examples/embed_minimal
# Inputs: MODE SOURCE_DIR BUILD_DIR WORK_DIR GENERATOR
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})

function(run)
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${WORK_DIR} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

set(launcher "")
find_program(CCACHE ccache)
if(CCACHE)
  set(launcher -DCMAKE_CXX_COMPILER_LAUNCHER=${CCACHE})
endif()

if(MODE STREQUAL "find_package")
  # Install, then move the prefix: the package must work wherever it lands.
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/staging)
  file(RENAME ${WORK_DIR}/staging ${WORK_DIR}/prefix)
  set(config_dir ${WORK_DIR}/prefix/lib/cmake/Tidewater)
  if(NOT EXISTS ${config_dir}/TidewaterConfig.cmake)
    message(FATAL_ERROR "TidewaterConfig.cmake was not installed")
  endif()
  # No path of the build machine in the exported files.
  file(GLOB exported ${config_dir}/*.cmake)
  foreach(f ${exported})
    file(READ ${f} text)
    foreach(path ${SOURCE_DIR} ${BUILD_DIR} ${WORK_DIR}/staging /usr/lib /usr/include)
      string(FIND "${text}" "${path}" at)
      if(NOT at EQUAL -1)
        message(FATAL_ERROR "${f} names ${path}, a path of the build machine")
      endif()
    endforeach()
  endforeach()
  foreach(f include/tidewater/scene_bake.hpp include/tidewater/render/renderer.hpp share/tidewater/presets/ocean_rolling.json
            share/tidewater/scenes/default.json ${config_dir}/TidewaterRenderTargets.cmake)
    if(NOT EXISTS ${WORK_DIR}/prefix/${f} AND NOT EXISTS ${f})
      message(FATAL_ERROR "${f} was not installed")
    endif()
  endforeach()
  # Installed headers hold what hosts call; the internal ones stay in the source tree.
  if(EXISTS ${WORK_DIR}/prefix/include/tidewater/detail)
    message(FATAL_ERROR "internal headers (tidewater/detail) were installed")
  endif()
  # Tidewater::core alone on a machine without Vulkan: find_package must not need it.
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK_DIR}/build_core -G ${GENERATOR}
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=TRUE ${launcher})
  if(NOT last_output MATCHES "consumer: Tidewater::render not used")
    message(FATAL_ERROR "without Vulkan the consumer should build with Tidewater::core alone:\n${last_output}")
  endif()
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/build_core)
  run(${WORK_DIR}/build_core/consumer)
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK_DIR}/build -G ${GENERATOR}
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix ${launcher})
elseif(MODE STREQUAL "embed_minimal")
  # The smallest complete renderer host, against the installed package at a moved prefix.
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/staging)
  file(RENAME ${WORK_DIR}/staging ${WORK_DIR}/prefix)
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/embed_minimal -B ${WORK_DIR}/build -G ${GENERATOR}
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix ${launcher})
  run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
  run(${WORK_DIR}/build/embed_minimal_headless --frames 4 --out ${WORK_DIR}/frame.png)
  if(NOT last_output MATCHES "query matches the drawn frame" OR NOT EXISTS ${WORK_DIR}/frame.png)
    message(FATAL_ERROR "embed_minimal_headless did not draw and match:\n${last_output}")
  endif()
  message(STATUS "embed_minimal:\n${last_output}")
  return()
elseif(MODE STREQUAL "add_subdirectory")
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK_DIR}/build -G ${GENERATOR}
      -DCMAKE_BUILD_TYPE=Release -DTIDEWATER_SOURCE_DIR=${SOURCE_DIR} ${launcher})
else()
  message(FATAL_ERROR "unknown MODE ${MODE}")
endif()
run(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
run(${WORK_DIR}/build/consumer)
if(NOT last_output MATCHES "boat heave=")
  message(FATAL_ERROR "consumer printed unexpected output:\n${last_output}")
endif()
message(STATUS "${MODE}: consumer built and ran:\n${last_output}")
