// The one translation unit that compiles tinygltf's implementation (header-only library).
// Draco is deliberately not enabled here: gltf_draco.cpp decodes it with bounds checks.
#define TINYGLTF_IMPLEMENTATION
#include "renderer/scene/tinygltf_include.h"
