// Internal to the glTF loader: reading accessors with every reference and byte range checked
// (tinygltf 2.7 checks neither), sparse accessors applied.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/gltf_document.h"

namespace penumbra::scene {

// The accessor at INDEX (checked to exist; KEY names where it was referenced).
const tinygltf::Accessor& accessorAt(const GltfDocument& doc, int index, const std::string& key);

// VEC3 float (POSITION, NORMAL).
std::vector<glm::vec3> readVec3(const GltfDocument& doc, int index, const std::string& key);
// VEC2 float, or normalized unsigned byte/short (TEXCOORD_n).
std::vector<glm::vec2> readTexcoords(const GltfDocument& doc, int index, const std::string& key);
// SCALAR unsigned byte, short or int (indices).
std::vector<std::uint32_t> readIndices(const GltfDocument& doc, int index, const std::string& key);

}  // namespace penumbra::scene
