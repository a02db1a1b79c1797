// Reading a glTF file: JSON (from the file or the GLB container) type-checked, Draco extensions
// taken out, then tinygltf loads the buffers (external, data URI or GLB) and image bytes.
#include "renderer/scene/gltf_document.h"

#include <fstream>

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/core/json_field.h"
#include "renderer/core/regular_file.h"
#include "renderer/scene/asset_store.h"
#include "renderer/scene/glb_container.h"
#include "renderer/scene/gltf_uri.h"
#include "renderer/scene/json_file.h"

namespace penumbra::scene {
namespace {

bool isIgnorableExtension(const std::string& name) {
    return name == "KHR_draco_mesh_compression" || name == "KHR_texture_transform" ||
           name == "KHR_lights_punctual" || name.rfind("KHR_materials_", 0) == 0;
}

// Removes every primitive's Draco extension (and its indices, which tinygltf would otherwise
// require to have a bufferView) from DOC, returning them by (mesh, primitive).
std::map<std::pair<int, int>, DracoReference> takeDraco(nlohmann::json& doc) {
    std::map<std::pair<int, int>, DracoReference> found;
    auto meshes = doc.find("meshes");
    if (meshes == doc.end()) return found;
    for (std::size_t m = 0; m < meshes->size(); ++m) {
        auto& primitives = (*meshes)[m]["primitives"];
        for (std::size_t p = 0; p < primitives.size(); ++p) {
            auto& primitive = primitives[p];
            auto extensions = primitive.find("extensions");
            if (extensions == primitive.end()) continue;
            auto draco = extensions->find("KHR_draco_mesh_compression");
            if (draco == extensions->end()) continue;
            DracoReference ref;
            ref.buffer_view = (*draco)["bufferView"].get<int>();
            if (primitive.contains("indices")) ref.indices = primitive["indices"].get<int>();
            for (const auto& item : (*draco)["attributes"].items())
                ref.attributes[item.key()] = item.value().get<int>();
            found[{static_cast<int>(m), static_cast<int>(p)}] = ref;
            extensions->erase(draco);
            primitive.erase("indices");
        }
    }
    return found;
}

// Keeps image files' bytes undecoded (gltf_texture.cpp decodes the ones a material uses), and
// never reads bytes tinygltf took from a bufferView: they are checked and read later.
bool keepImageBytes(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                    const unsigned char* bytes, int size, void*) {
    image->as_is = true;
    if (image->bufferView < 0 && bytes && size > 0) image->image.assign(bytes, bytes + size);
    return true;
}

// What tinygltf's file callbacks see: the glTF's folder, and the files read from it.
struct FsContext {
    std::string base_dir;
    std::vector<std::string>* read = nullptr;
};

// File access for tinygltf: only regular files inside the glTF's folder (no fallback to the
// working directory), with the same size limit as the glTF itself; each file read is recorded
// under AssetStore's key for it.
bool fileExists(const std::string& path, void* user) {
    const auto* context = static_cast<const FsContext*>(user);
    return insideFolder(context->base_dir, path) && notRegularFileReason(path).empty();
}
std::string expandFilePath(const std::string& path, void*) {
    return path;
}
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                   void* user) {
    try {
        const std::string bytes = readTextFile(path, path, kMaxGltfFileBytes);
        out->assign(bytes.begin(), bytes.end());
        static_cast<FsContext*>(user)->read->push_back(AssetStore::pathKey(path));
        return true;
    } catch (const InputError& e) {
        if (err) *err = e.what();
        return false;
    }
}
bool refuseWrite(std::string*, const std::string&, const std::vector<unsigned char>&, void*) {
    return false;
}

std::string oneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    for (std::size_t i = 0; (i = text.find('\n', i)) != std::string::npos;)
        text.replace(i, 1, "; ");
    return text;
}

}  // namespace

void GltfDocument::fail(const std::string& key, const std::string& what) const {
    failAt(label, key, what);
}

GltfDocument readGltfDocument(const std::filesystem::path& path) {
    GltfDocument doc;
    doc.label = path.string();
    const std::string bytes = readTextFile(path, doc.label, kMaxGltfFileBytes);
    const bool binary = isGlb(bytes);
    GlbParts glb;
    if (binary) glb = splitGlb(bytes, doc.label);
    nlohmann::json json = parseJsonText(binary ? glb.json : bytes, doc.label);

    checkGltfJson(json, doc.label);
    readCamerasAndLights(json, doc);
    if (const auto required = json.find("extensionsRequired"); required != json.end())
        for (const auto& name : *required)
            if (!isIgnorableExtension(name.get<std::string>()))
                doc.fail("extensionsRequired",
                         "unsupported extension '" + quoteText(name.get<std::string>()) + "'");
    doc.draco = takeDraco(json);

    FsContext context{path.parent_path().string(), &doc.external_files};
    if (context.base_dir.empty()) context.base_dir = ".";
    const std::string& base_dir = context.base_dir;
    const std::vector<std::string> image_uris = confineAssetUris(json, base_dir, doc);
    tinygltf::TinyGLTF loader;
    loader.SetImageLoader(keepImageBytes, nullptr);
    loader.SetFsCallbacks({fileExists, expandFilePath, readWholeFile, refuseWrite, &context});
    std::string err;
    std::string warn;
    bool ok = false;
    try {
        const std::string text = json.dump();
        if (binary) {
            const std::string glb_bytes = assembleGlb(text, glb);
            ok = loader.LoadBinaryFromMemory(
                &doc.model, &err, &warn, reinterpret_cast<const unsigned char*>(glb_bytes.data()),
                static_cast<unsigned int>(glb_bytes.size()), base_dir);
        } else {
            ok = loader.LoadASCIIFromString(&doc.model, &err, &warn, text.data(),
                                            static_cast<unsigned int>(text.size()), base_dir);
        }
    } catch (const std::exception& e) {
        throw InputError(doc.label + ": " + e.what());
    }
    if (!ok) throw InputError(doc.label + ": " + oneLine(err.empty() ? warn : err));
    for (std::size_t i = 0; i < doc.model.images.size() && i < image_uris.size(); ++i)
        doc.model.images[i].uri = image_uris[i];  // as written, not as rewritten for tinygltf
    return doc;
}

}  // namespace penumbra::scene
