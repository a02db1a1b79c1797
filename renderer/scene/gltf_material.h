// Internal to the glTF loader: glTF materials turned into Model materials on first use (base
// colour factor and base-colour texture), each texture image decoded once.
#pragma once

#include <map>
#include <string>

#include "renderer/scene/gltf_document.h"
#include "renderer/scene/scene.h"

namespace penumbra::scene {

class MaterialTable {
public:
    MaterialTable(const GltfDocument& doc, Model& model) : doc_(doc), model_(model) {}

    // The Model::materials index for glTF material GLTF_MATERIAL (-1: the default material),
    // added on first use. KEY names the primitive's "material" for errors.
    int indexOf(int gltf_material, const std::string& key);

private:
    Material convert(int index);
    int textureOf(int image);

    const GltfDocument& doc_;
    Model& model_;
    std::map<int, int> materials_;  // glTF material -> Model::materials index
    std::map<int, int> textures_;   // glTF image -> Model::textures index
};

}  // namespace penumbra::scene
