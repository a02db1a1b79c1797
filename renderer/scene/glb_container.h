// Internal to the glTF loader: the binary glTF (GLB) container, split into its JSON and BIN
// chunks with every length checked, and put back together for tinygltf.
#pragma once

#include <string>

namespace penumbra::scene {

struct GlbParts {
    std::string json;  // the JSON chunk, trailing padding removed
    std::string bin;   // the first BIN chunk
    bool has_bin = false;
};

// True when BYTES start with the GLB magic "glTF".
bool isGlb(const std::string& bytes);

// Splits a GLB file. Throws InputError("<label>: ...") on a truncated or malformed container.
GlbParts splitGlb(const std::string& bytes, const std::string& label);

// A GLB holding JSON and PARTS' BIN chunk, each chunk padded to 4 bytes.
std::string assembleGlb(const std::string& json, const GlbParts& parts);

}  // namespace penumbra::scene
