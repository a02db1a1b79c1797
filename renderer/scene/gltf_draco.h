// Internal to the glTF loader: decoding a KHR_draco_mesh_compression primitive with Draco,
// checking what tinygltf 2.7's own Draco path does not (missing attributes, face indices).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/gltf_document.h"

namespace penumbra::scene {

struct DracoGeometry {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // empty when the primitive has none
    std::vector<glm::vec2> uvs;          // TEXCOORD_0, empty when absent
    std::vector<std::uint32_t> indices;  // triangles
};

// KEY names the primitive ("meshes.0.primitives.1"). MAX_TRIANGLES is checked before copying.
DracoGeometry decodeDraco(const GltfDocument& doc, const DracoReference& ref,
                          const std::string& key, std::size_t max_triangles);

}  // namespace penumbra::scene
