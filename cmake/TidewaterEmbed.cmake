# tidewater_embed_text(<output.cpp> <namespace> <file>...)
# Generates a C++ source that holds each file's text as a std::string_view,
# looked up by the file's stem (e.g. "ocean_rolling"). Regenerated when any
# input changes, so examples/presets stay the single source of truth.
function(tidewater_embed_text output namespace)
  set(inputs ${ARGN})
  add_custom_command(
    OUTPUT ${output}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${output} -DNAMESPACE=${namespace}
            "-DINPUTS=${inputs}" -P ${PROJECT_SOURCE_DIR}/cmake/TidewaterEmbedScript.cmake
    DEPENDS ${inputs} ${PROJECT_SOURCE_DIR}/cmake/TidewaterEmbedScript.cmake
    COMMENT "Embedding ${namespace} text resources"
    VERBATIM)
endfunction()
