# Warnings and sanitizers shared by every Tidewater target.
# Use tidewater_target_defaults(<target>) on each target the project builds.

function(tidewater_target_defaults target)
  if(CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    target_compile_options(${target} PRIVATE
      -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion
      -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Wunused
      -Woverloaded-virtual -Wdouble-promotion -Wformat=2
      -Wimplicit-fallthrough)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
      # Clang also flags a float widened to double where it is passed or stored, which is
      # exact; GCC's builds check the promotions inside arithmetic.
      target_compile_options(${target} PRIVATE -Wno-double-promotion)
    endif()
    if(TIDEWATER_WARNINGS_AS_ERRORS)
      target_compile_options(${target} PRIVATE -Werror)
    endif()
  elseif(MSVC)
    target_compile_options(${target} PRIVATE /W4 $<$<BOOL:${TIDEWATER_WARNINGS_AS_ERRORS}>:/WX>)
  endif()
endfunction()

if(TIDEWATER_SANITIZE STREQUAL "thread")
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "TIDEWATER_SANITIZE=thread needs GCC or Clang")
  endif()
  # ThreadSanitizer sees only what is instrumented: Debian's oneTBB is not, so its
  # hand-offs between threads are invisible to it. detail::parallel_chunks runs on plain
  # threads in this build (parallel.cpp), and every thread Tidewater makes is one TSan sees.
  add_compile_options(-fsanitize=thread -fno-omit-frame-pointer)
  add_compile_definitions(TIDEWATER_THREAD_SANITIZER=1)
  add_link_options(-fsanitize=thread)
elseif(TIDEWATER_SANITIZE)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "GNU|Clang")
    message(FATAL_ERROR "TIDEWATER_SANITIZE needs GCC or Clang")
  endif()
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined)
  # Sanitizer instrumentation makes GCC report maybe-uninitialized inside
  # third-party headers (xsimd's rem_pio2); that warning is meaningless here.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-Wno-maybe-uninitialized)
  endif()
  add_link_options(-fsanitize=address,undefined)
endif()

# libFuzzer: every target is instrumented for coverage (the fuzz targets link the fuzzer's
# main; the unit tests of the same build run as they are).
if(TIDEWATER_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR NOT TIDEWATER_SANITIZE OR TIDEWATER_SANITIZE STREQUAL "thread")
    message(FATAL_ERROR "TIDEWATER_FUZZ needs Clang and TIDEWATER_SANITIZE=ON (address)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
