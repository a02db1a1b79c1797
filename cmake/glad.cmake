# The glad2 GL 4.5 core loader, generated at configure time from Debian's python3-glad
# (--reproducible: from the packaged spec, no network). Never committed.
set(PENUMBRA_GLAD_DIR ${CMAKE_BINARY_DIR}/glad)
if(NOT EXISTS ${PENUMBRA_GLAD_DIR}/src/gl.c)
    execute_process(
        COMMAND /usr/bin/python3 -m glad --quiet --api gl:core=4.5 --extensions GL_KHR_debug
                --out-path ${PENUMBRA_GLAD_DIR} --reproducible c
        RESULT_VARIABLE _glad_result OUTPUT_QUIET ERROR_VARIABLE _glad_err)
    if(NOT _glad_result EQUAL 0)
        message(FATAL_ERROR "glad generation failed (is python3-glad installed?): ${_glad_err}")
    endif()
endif()
add_library(penumbra_glad STATIC ${PENUMBRA_GLAD_DIR}/src/gl.c)
target_include_directories(penumbra_glad PUBLIC ${PENUMBRA_GLAD_DIR}/include)
set_target_properties(penumbra_glad PROPERTIES POSITION_INDEPENDENT_CODE ON)
