// The loaders under fuzzing, each one input at a time: the scene loader, the glTF loader, the
// image readers (OpenImageIO files and stb/OIIO glTF textures) and compare's EXR reader.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace penumbra::fuzz {

// The target names: "scene", "gltf", "image", "exr".
const std::vector<std::string>& targetNames();

// Feeds DATA to TARGET, written as a file under WORK where the loader needs a path (WORK holds
// links to the shipped scene assets, so a scene may name them). Returns normally when the input
// was loaded or refused the documented way (InputError, UnreadableImage); any other exception
// propagates (a finding), as do crashes and hangs (the driver sees those).
void runTarget(const std::string& target, const std::uint8_t* data, std::size_t size,
               const std::filesystem::path& work);

// The file name the input gets for TARGET given the seed's name: the extension picks the
// reader (".glb" or ".gltf", ".exr", ".hdr", ".png").
std::string inputName(const std::string& target, const std::string& seed_name);

}  // namespace penumbra::fuzz
