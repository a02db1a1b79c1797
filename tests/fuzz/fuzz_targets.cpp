// Fuzz targets: see fuzz_targets.h. Each writes the input where its loader reads it and calls
// the loader exactly as the commands do.
#include "tests/fuzz/fuzz_targets.h"

#include <algorithm>
#include <fstream>
#include <stdexcept>

#include "renderer/core/error.h"
#include "renderer/output/exr.h"
#include "renderer/scene/gltf_document.h"
#include "renderer/scene/gltf_loader.h"
#include "renderer/scene/gltf_texture.h"
#include "renderer/scene/image_file.h"
#include "renderer/scene/scene_source.h"

namespace penumbra::fuzz {
namespace {

std::filesystem::path writeInput(const std::filesystem::path& path, const std::uint8_t* data,
                                 std::size_t size) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    if (!out) throw std::runtime_error("fuzz: cannot write " + path.string());
    return path;
}

std::string extensionOf(const std::uint8_t* data, std::size_t size) {
    auto starts = [&](const char* magic, std::size_t n) {
        return size >= n && std::equal(magic, magic + n, reinterpret_cast<const char*>(data));
    };
    if (starts("\x76\x2f\x31\x01", 4)) return ".exr";
    if (starts("#?", 2)) return ".hdr";
    if (starts("glTF", 4)) return ".glb";
    return ".png";
}

}  // namespace

const std::vector<std::string>& targetNames() {
    static const std::vector<std::string> names = {"scene", "gltf", "image", "exr"};
    return names;
}

std::string inputName(const std::string& target, const std::string& seed_name) {
    if (target == "scene") return "fuzz.json";
    if (target == "exr") return "fuzz.exr";
    const std::string ext = std::filesystem::path(seed_name).extension().string();
    if (target == "gltf") return ext == ".gltf" ? "fuzz.gltf" : "fuzz.glb";
    return "fuzz" + (ext.empty() ? std::string(".png") : ext);
}

void runTarget(const std::string& target, const std::uint8_t* data, std::size_t size,
               const std::filesystem::path& work) {
    auto refusedIsFine = [](auto&& load) {
        try {
            load();
        } catch (const InputError&) {
        } catch (const output::UnreadableImage&) {
        }
    };
    if (target == "scene") {
        refusedIsFine([&] {
            (void)scene::SceneSource::load(writeInput(work / "fuzz.json", data, size), {});
        });
    } else if (target == "gltf") {
        // The loader picks the container by name: the first bytes say which it is.
        const bool binary = size >= 4 && std::equal(data, data + 4, "glTF");
        refusedIsFine([&] {
            (void)scene::loadGltf(
                writeInput(work / (binary ? "fuzz.glb" : "fuzz.gltf"), data, size));
        });
    } else if (target == "image") {
        // Every reader a scene's images meet: from a file (named by its magic; .exr through
        // output/exr.h's reader, the others through OIIO), and the glTF texture decoder
        // (stb_image; Radiance HDR through OIIO from memory).
        const std::string ext = extensionOf(data, size);
        refusedIsFine([&] {
            (void)scene::readFloatImage(writeInput(work / ("fuzz" + ext), data, size), "fuzz",
                                        {".exr", ".hdr", ".png"}, "an image", 16384, 3);
        });
        refusedIsFine([&] {
            scene::GltfDocument doc;
            doc.label = "fuzz.gltf";
            doc.model.images.emplace_back();
            doc.model.images.back().image.assign(data, data + size);
            (void)scene::decodeGltfImage(doc, 0);
        });
    } else if (target == "exr") {
        refusedIsFine([&] { (void)output::readExr(writeInput(work / "fuzz.exr", data, size)); });
    } else {
        throw std::invalid_argument("fuzz: unknown target '" + target + "'");
    }
}

}  // namespace penumbra::fuzz
