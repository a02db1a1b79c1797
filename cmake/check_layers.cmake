# Include order between the layers: fails (naming file, line and include) when a file under
# renderer/<layer>/ or cli/ includes a folder its layer may not see, or when a technique reads
# a parameter by its key's text instead of its typed key. Run by the build (target
# penumbra_layers_checked) and by ctest (unit.layers): cmake -DSOURCE_DIR=... -P check_layers.cmake
cmake_minimum_required(VERSION 3.25)

# The folders each layer may include besides its own, lowest layer first (DESIGN.md, Layers).
set(_allowed_core "")
set(_allowed_output core)
set(_allowed_scene core output)  # output/exr.h reads OpenEXR images
set(_allowed_gl core)
set(_allowed_passes core scene output gl)
set(_allowed_frame core scene output gl passes)
set(_allowed_techniques core scene output gl passes frame)
set(_allowed_app core scene output gl passes frame techniques)
set(_allowed_cli core scene output gl passes frame techniques app)
set(_allowed_oiio core)  # libpenumbra_oiio.so: core/oiio_module.h's interface only
set(_layers core output scene gl passes frame techniques app cli oiio)

if(NOT SOURCE_DIR)
    message(FATAL_ERROR "check_layers: pass -DSOURCE_DIR=<the source tree>")
endif()

set(_problems "")
set(_count 0)
# A folder under renderer/ that is no layer would escape the check: name it above first.
file(GLOB _folders LIST_DIRECTORIES true ${SOURCE_DIR}/renderer/*)
foreach(folder ${_folders})
    get_filename_component(_name ${folder} NAME)
    if(IS_DIRECTORY ${folder} AND NOT _name IN_LIST _layers)
        string(APPEND _problems "  renderer/${_name}/: not a layer of cmake/check_layers.cmake\n")
    endif()
endforeach()
foreach(layer ${_layers})
    if(layer STREQUAL "cli")
        set(_dir ${SOURCE_DIR}/cli)
    else()
        set(_dir ${SOURCE_DIR}/renderer/${layer})
    endif()
    file(GLOB_RECURSE _files ${_dir}/*.h ${_dir}/*.cpp)
    foreach(file ${_files})
        math(EXPR _count "${_count} + 1")
        file(STRINGS ${file} _includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"(renderer/[A-Za-z0-9_]+|cli)/")
        foreach(line ${_includes})
            string(REGEX REPLACE "^[^\"]*\"([A-Za-z0-9_/]+)/[^/\"]*\".*$" "\\1" _to "${line}")
            string(REGEX REPLACE "^renderer/([A-Za-z0-9_]+).*$" "\\1" _to "${_to}")
            if(_to STREQUAL layer)
                continue()
            endif()
            list(FIND _allowed_${layer} ${_to} _at)
            if(_at EQUAL -1)
                file(RELATIVE_PATH _rel ${SOURCE_DIR} ${file})
                string(STRIP "${line}" line)
                string(REPLACE ";" ", " _may "${_allowed_${layer}}")
                string(APPEND _problems "  ${_rel}: ${line}: ${layer}/ may include only ${_may}\n")
            endif()
        endforeach()
    endforeach()
endforeach()

if(_problems)
    message(FATAL_ERROR "check_layers: includes that run back up the layers "
            "(core < output < scene, core < gl; scene, gl < passes < frame < techniques < app "
            "< cli; core < oiio):\n${_problems}")
endif()
message(STATUS "check_layers: ${_count} files include only the layers below them")

# A technique reads its parameters through typed keys (Params::get(kKey), params.h), declared
# once beside its table: a key spelled again as text in a getter is refused here.
file(GLOB_RECURSE _technique_files ${SOURCE_DIR}/renderer/techniques/*.h
     ${SOURCE_DIR}/renderer/techniques/*.cpp)
foreach(file ${_technique_files})
    file(STRINGS ${file} _reads REGEX "\\.get(Int|Float|Bool|String)\\(\"")
    foreach(line ${_reads})
        file(RELATIVE_PATH _rel ${SOURCE_DIR} ${file})
        string(STRIP "${line}" line)
        string(APPEND _problems "  ${_rel}: ${line}: read it with Params::get and its key\n")
    endforeach()
endforeach()
if(_problems)
    message(FATAL_ERROR "check_layers: parameters read by a key's text:\n${_problems}")
endif()
