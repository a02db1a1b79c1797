// glTF materials: pbrMetallicRoughness base colour (clamped to [0, 1]) and its texture when it
// uses TEXCOORD_0; other material properties and extensions are not read.
#include "renderer/scene/gltf_material.h"

#include <algorithm>
#include <cmath>

#include "renderer/scene/gltf_texture.h"

namespace penumbra::scene {

int MaterialTable::indexOf(int gltf_material, const std::string& key) {
    if (gltf_material >= static_cast<int>(doc_.model.materials.size()))
        doc_.fail(key, "material " + std::to_string(gltf_material) + " does not exist");
    gltf_material = std::max(gltf_material, -1);
    const auto found = materials_.find(gltf_material);
    if (found != materials_.end()) return found->second;
    const Material material = gltf_material >= 0 ? convert(gltf_material) : Material{};
    const int index = static_cast<int>(model_.materials.size());
    model_.materials.push_back(material);
    materials_.emplace(gltf_material, index);
    return index;
}

Material MaterialTable::convert(int index) {
    const std::string key = "materials." + std::to_string(index) + ".pbrMetallicRoughness";
    const tinygltf::PbrMetallicRoughness& pbr =
        doc_.model.materials[static_cast<std::size_t>(index)].pbrMetallicRoughness;
    const auto& factor = pbr.baseColorFactor;
    if (factor.size() != 4 ||
        !std::all_of(factor.begin(), factor.end(), [](double v) { return std::isfinite(v); }))
        doc_.fail(key + ".baseColorFactor", "expected 4 finite numbers");
    Material material;
    for (int c = 0; c < 4; ++c)
        material.base_color[c] =
            static_cast<float>(std::clamp(factor[static_cast<std::size_t>(c)], 0.0, 1.0));
    const int texture = pbr.baseColorTexture.index;
    if (texture < 0 || pbr.baseColorTexture.texCoord != 0) return material;  // no TEXCOORD_1
    if (static_cast<std::size_t>(texture) >= doc_.model.textures.size())
        doc_.fail(key + ".baseColorTexture.index",
                  "texture " + std::to_string(texture) + " does not exist");
    const int image = doc_.model.textures[static_cast<std::size_t>(texture)].source;
    if (image < 0) return material;  // an image only an extension provides (KTX2, WebP)
    if (static_cast<std::size_t>(image) >= doc_.model.images.size())
        doc_.fail("textures." + std::to_string(texture) + ".source",
                  "image " + std::to_string(image) + " does not exist");
    material.texture = textureOf(image);
    return material;
}

int MaterialTable::textureOf(int image) {
    const auto found = textures_.find(image);
    if (found != textures_.end()) return found->second;
    const int index = static_cast<int>(model_.textures.size());
    model_.textures.push_back(decodeGltfImage(doc_, image));
    textures_.emplace(image, index);
    return index;
}

}  // namespace penumbra::scene
