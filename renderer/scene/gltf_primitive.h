// Internal to the glTF loader: one mesh primitive read into model-space indexed triangles
// (strips and fans converted, indices and values checked, missing normals computed).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "renderer/scene/gltf_document.h"

namespace penumbra::scene {

struct PrimitiveGeometry {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;      // one per position, unit length
    std::vector<glm::vec2> uvs;          // empty or one per position
    std::vector<std::uint32_t> indices;  // triangles, counter-clockwise front faces
};

// Vertex and triangle counts from the accessors' counts, before any data is read, for limits.
struct PrimitiveSize {
    std::size_t vertices = 0;
    std::size_t triangles = 0;
};
PrimitiveSize primitiveSize(const GltfDocument& doc, int mesh, int primitive);

// Reads meshes[MESH].primitives[PRIMITIVE]. Throws InputError naming the key at fault.
PrimitiveGeometry readPrimitive(const GltfDocument& doc, int mesh, int primitive,
                                std::size_t max_triangles);

// Area-weighted vertex normals of TRIANGLES; (0, 1, 0) where a vertex has no area around it.
std::vector<glm::vec3> smoothNormals(const std::vector<glm::vec3>& positions,
                                     const std::vector<std::uint32_t>& triangles);

}  // namespace penumbra::scene
