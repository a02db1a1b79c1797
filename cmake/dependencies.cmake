# Third-party libraries, all from Debian 12 packages (scripts/packages.txt).
find_package(PkgConfig REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(glm REQUIRED)
find_package(OpenEXR REQUIRED)
find_package(Imath REQUIRED)
find_package(draco REQUIRED)
find_package(OpenImageIO REQUIRED)
find_package(embree 3 REQUIRED)
pkg_check_modules(EGL REQUIRED IMPORTED_TARGET egl)
pkg_check_modules(STB REQUIRED IMPORTED_TARGET stb)

# OpenImageIO 2.4's target names /usr/include/opencv4 as an include directory; without OpenCV
# installed that path does not exist and configuring fails, so filter it out.
get_target_property(_oiio_inc OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
if(_oiio_inc)
    list(FILTER _oiio_inc EXCLUDE REGEX "opencv")
    set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_inc}")
endif()
get_target_property(_oiio_util_inc OpenImageIO::OpenImageIO_Util INTERFACE_INCLUDE_DIRECTORIES)
if(_oiio_util_inc)
    list(FILTER _oiio_util_inc EXCLUDE REGEX "opencv")
    set_target_properties(OpenImageIO::OpenImageIO_Util PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_util_inc}")
endif()

# OpenImageIO is not among them: it pulls in about 260 shared libraries, whose loading cost
# every process a quarter of a second, so only libpenumbra_oiio.so links it (CMakeLists.txt).
add_library(penumbra_deps INTERFACE)
target_link_libraries(penumbra_deps INTERFACE
    nlohmann_json::nlohmann_json glm::glm OpenEXR::OpenEXR Imath::Imath
    embree PkgConfig::EGL PkgConfig::STB ${CMAKE_DL_LIBS})
target_include_directories(penumbra_deps INTERFACE ${draco_INCLUDE_DIRS} /usr/include/stb)
target_link_libraries(penumbra_deps INTERFACE draco::draco)
target_compile_definitions(penumbra_deps INTERFACE GLM_FORCE_RADIANS)
