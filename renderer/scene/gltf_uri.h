// Internal to the glTF loader: external buffer and image URIs confined to the glTF's folder,
// resolved the same way whether relative or absolute (weakly canonical, then a folder check).
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace penumbra::scene {

struct GltfDocument;

// URI percent-decoding ("%20" -> " "); other characters as they are.
std::string percentDecode(const std::string& uri);

// True when FILE, made weakly canonical, lies inside the folder BASE (also made canonical).
bool insideFolder(const std::filesystem::path& base, const std::filesystem::path& file);

// Checks every external buffers.N.uri and images.N.uri of JSON: inside BASE (else DOC.fail),
// and for buffers a regular file. Rewrites each to its path relative to BASE, encoded so that
// tinygltf's decoding gives it back. Returns the images' original URIs (for messages).
std::vector<std::string> confineAssetUris(nlohmann::json& json, const std::filesystem::path& base,
                                          const GltfDocument& doc);

}  // namespace penumbra::scene
