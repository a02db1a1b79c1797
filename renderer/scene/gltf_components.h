// glTF's accessor component and element types: their sizes and names for messages, and one
// component decoded to a double (normalized integers mapped to [0, 1] or [-1, 1]).
#pragma once

#include <cstddef>

#include "renderer/scene/tinygltf_include.h"

namespace penumbra::scene {

constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE;
constexpr int kUByte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE;
constexpr int kShort = TINYGLTF_COMPONENT_TYPE_SHORT;
constexpr int kUShort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
constexpr int kUInt = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

// Bytes of one component of TYPE (TINYGLTF_COMPONENT_TYPE_*).
std::size_t componentSize(int type);
// TYPE's name ("UNSIGNED_SHORT") and an element TYPE's name ("VEC3"), for messages.
const char* componentName(int type);
const char* typeName(int type);
// The component of TYPE at P, normalized when NORMALIZED.
double decode(const unsigned char* p, int type, bool normalized);

}  // namespace penumbra::scene
