// Internal to the glTF loader: decoding a glTF image (PNG, JPEG, ... via stb_image) into an
// RGBA8 texture, its size checked before the pixels are decoded.
#pragma once

#include "renderer/scene/gltf_document.h"
#include "renderer/scene/scene.h"

namespace penumbra::scene {

constexpr int kMaxTextureSize = 16384;  // width and height limit, pixels

// Decodes images[INDEX] of DOC. Throws InputError naming "images.<INDEX>".
Texture decodeGltfImage(const GltfDocument& doc, int index);

}  // namespace penumbra::scene
