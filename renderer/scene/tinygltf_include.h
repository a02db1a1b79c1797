// tinygltf's declarations for this module's glTF files, with the warnings its header raises
// under our warning flags silenced. The implementation is compiled once, in tinygltf_impl.cpp.
#pragma once

// Images are decoded by gltf_texture.cpp (stb from libstb) and Draco by gltf_draco.cpp, both
// with bounds checks tinygltf 2.7 lacks; tinygltf only parses and loads buffers.
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wnull-dereference"
#pragma GCC diagnostic ignored "-Wcast-align"
#pragma GCC diagnostic ignored "-Wimplicit-fallthrough"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wunused-variable"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <tiny_gltf.h>
#pragma GCC diagnostic pop
