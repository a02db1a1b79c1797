# Shaders: glsl/ is embedded into the binary (includes resolved) and every entry point is
# compiled by glslangValidator at build time, so a GLSL error fails the build.
file(GLOB_RECURSE PENUMBRA_GLSL_FILES CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/glsl/*.glsl
     ${CMAKE_SOURCE_DIR}/glsl/*.vert ${CMAKE_SOURCE_DIR}/glsl/*.frag ${CMAKE_SOURCE_DIR}/glsl/*.comp)
set(PENUMBRA_SHADER_SOURCE ${CMAKE_BINARY_DIR}/generated/embedded_shaders.cpp)
set(_stamp ${CMAKE_BINARY_DIR}/generated/shaders_checked.stamp)
find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
add_custom_command(
    OUTPUT ${PENUMBRA_SHADER_SOURCE}
    COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/cmake/embed_shaders.py embed
            ${CMAKE_SOURCE_DIR}/glsl ${PENUMBRA_SHADER_SOURCE}
    DEPENDS ${PENUMBRA_GLSL_FILES} ${CMAKE_SOURCE_DIR}/cmake/embed_shaders.py
    COMMENT "Embedding shaders")
add_custom_command(
    OUTPUT ${_stamp}
    COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/cmake/embed_shaders.py check
            ${CMAKE_SOURCE_DIR}/glsl ${CMAKE_BINARY_DIR}/generated/glsl_check ${GLSLANG_VALIDATOR}
    COMMAND ${CMAKE_COMMAND} -E touch ${_stamp}
    DEPENDS ${PENUMBRA_GLSL_FILES} ${CMAKE_SOURCE_DIR}/cmake/embed_shaders.py
    COMMENT "Checking shaders with glslangValidator")
add_custom_target(penumbra_shaders_checked DEPENDS ${_stamp})
