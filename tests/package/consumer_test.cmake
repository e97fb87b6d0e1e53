# Builds examples/consumer against Tidewater in one of two ways and runs it.
#   MODE=find_package      install the build tree to a prefix, then find_package(Tidewater)
#   MODE=add_subdirectory  add Tidewater's source tree with add_subdirectory
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
  run(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
  if(NOT EXISTS ${WORK_DIR}/prefix/lib/cmake/Tidewater/TidewaterConfig.cmake
     AND NOT EXISTS ${WORK_DIR}/prefix/lib/x86_64-linux-gnu/cmake/Tidewater/TidewaterConfig.cmake)
    message(FATAL_ERROR "TidewaterConfig.cmake was not installed")
  endif()
  # Installed headers hold what hosts call; the internal ones stay in the source tree.
  if(EXISTS ${WORK_DIR}/prefix/include/tidewater/detail)
    message(FATAL_ERROR "internal headers (tidewater/detail) were installed")
  endif()
  if(NOT EXISTS ${WORK_DIR}/prefix/include/tidewater/scene_bake.hpp)
    message(FATAL_ERROR "the public header tidewater/scene_bake.hpp was not installed")
  endif()
  run(${CMAKE_COMMAND} -S ${SOURCE_DIR}/examples/consumer -B ${WORK_DIR}/build -G ${GENERATOR}
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix ${launcher})
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
