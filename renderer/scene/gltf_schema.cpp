// Type checks on a glTF document's JSON before tinygltf reads it: the fields the loader uses must
// have their glTF types, indices must be non-negative integers, bufferViews must fit their buffers.
#include <string_view>

#include "renderer/scene/gltf_document.h"
#include "renderer/scene/gltf_schema_checker.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;

std::size_t arrayCount(const json& doc, const char* name) {
    const json* v = SchemaChecker::find(doc, name);
    return v && v->is_array() ? v->size() : 0;
}

void checkMeshes(const SchemaChecker& c, const json& doc) {
    const std::size_t accessors = arrayCount(doc, "accessors");
    c.eachObject(doc, "", "meshes", [&](const json& mesh, const std::string& key) {
        const json* primitives = SchemaChecker::find(mesh, "primitives");
        if (!primitives) c.fail(key, "no primitives");
        c.eachObject(mesh, key, "primitives", [&](const json& p, const std::string& pkey) {
            const json* attributes = SchemaChecker::find(p, "attributes");
            if (!attributes) c.fail(pkey, "no attributes");
            const std::string akey = joinKey(pkey, "attributes");
            c.object(*attributes, akey);
            for (const auto& item : attributes->items())
                c.reference(item.value(), joinKey(akey, item.key()), accessors, "accessor");
            if (const json* indices = SchemaChecker::find(p, "indices"))
                c.reference(*indices, joinKey(pkey, "indices"), accessors, "accessor");
            c.optIndex(p, pkey, "material");
            c.optIndex(p, pkey, "mode");
            const json* extensions = SchemaChecker::find(p, "extensions");
            if (!extensions) return;
            const std::string ekey = joinKey(pkey, "extensions");
            c.object(*extensions, ekey);
            const json* draco = SchemaChecker::find(*extensions, "KHR_draco_mesh_compression");
            if (!draco) return;
            const std::string dkey = joinKey(ekey, "KHR_draco_mesh_compression");
            c.object(*draco, dkey);
            const json* view = SchemaChecker::find(*draco, "bufferView");
            const json* ids = SchemaChecker::find(*draco, "attributes");
            if (!view || !ids) c.fail(dkey, "needs bufferView and attributes");
            c.index(*view, joinKey(dkey, "bufferView"));
            c.indexMap(*ids, joinKey(dkey, "attributes"));
        });
    });
}

void checkAccessors(const SchemaChecker& c, const json& doc) {
    c.eachObject(doc, "", "accessors", [&](const json& a, const std::string& key) {
        c.optIndex(a, key, "bufferView");
        c.optIndex(a, key, "byteOffset");
        c.optIndex(a, key, "componentType");
        c.optIndex(a, key, "count", 1);
        c.optString(a, key, "type");
        if (const json* n = SchemaChecker::find(a, "normalized"))
            c.boolean(*n, key + ".normalized");
        const json* sparse = SchemaChecker::find(a, "sparse");
        if (!sparse) return;
        const std::string skey = joinKey(key, "sparse");
        c.object(*sparse, skey);
        c.optIndex(*sparse, skey, "count", 1);
        for (const char* part : {"indices", "values"}) {
            const json* p = SchemaChecker::find(*sparse, part);
            if (!p) c.fail(skey, std::string("no ") + part);
            const std::string pkey = joinKey(skey, part);
            c.object(*p, pkey);
            c.optIndex(*p, pkey, "bufferView");
            c.optIndex(*p, pkey, "byteOffset");
            c.optIndex(*p, pkey, "componentType");
        }
    });
}

void checkBuffers(const SchemaChecker& c, const json& doc) {
    std::vector<long> lengths;
    c.eachObject(doc, "", "buffers", [&](const json& b, const std::string& key) {
        c.optString(b, key, "uri");
        const json* length = SchemaChecker::find(b, "byteLength");
        if (!length) c.fail(key, "no byteLength");
        lengths.push_back(c.index(*length, key + ".byteLength"));
    });
    c.eachObject(doc, "", "bufferViews", [&](const json& v, const std::string& key) {
        const json* buffer = SchemaChecker::find(v, "buffer");
        const json* length = SchemaChecker::find(v, "byteLength");
        if (!buffer || !length) c.fail(key, "needs buffer and byteLength");
        const long b = c.index(*buffer, key + ".buffer");
        const long n = c.index(*length, key + ".byteLength", 1);
        long offset = 0;
        if (const json* o = SchemaChecker::find(v, "byteOffset"))
            offset = c.index(*o, key + ".byteOffset");
        if (const json* s = SchemaChecker::find(v, "byteStride")) {
            const long stride = c.index(*s, key + ".byteStride", 4);
            if (stride > 252 || stride % 4 != 0)
                c.fail(key + ".byteStride", "must be a multiple of 4 in 4..252");
        }
        if (static_cast<std::size_t>(b) >= lengths.size())
            c.fail(key + ".buffer", "buffer " + std::to_string(b) + " does not exist");
        if (offset + n > lengths[static_cast<std::size_t>(b)])
            c.fail(key, "byteOffset + byteLength = " + std::to_string(offset + n) +
                            " exceeds the byteLength of buffers." + std::to_string(b) + " (" +
                            std::to_string(lengths[static_cast<std::size_t>(b)]) + ")");
    });
}

void checkNodes(const SchemaChecker& c, const json& doc) {
    c.optIndex(doc, "", "scene");
    c.eachObject(doc, "", "scenes",
                 [&](const json& s, const std::string& key) { c.optIndexArray(s, key, "nodes"); });
    c.eachObject(doc, "", "nodes", [&](const json& n, const std::string& key) {
        c.optIndexArray(n, key, "children");
        c.optIndex(n, key, "mesh");
        c.optNumbers(n, key, "matrix", 16);
        c.optNumbers(n, key, "translation", 3);
        c.optNumbers(n, key, "rotation", 4);
        c.optNumbers(n, key, "scale", 3);
    });
}

void checkMaterials(const SchemaChecker& c, const json& doc) {
    c.eachObject(doc, "", "materials", [&](const json& m, const std::string& key) {
        const json* pbr = SchemaChecker::find(m, "pbrMetallicRoughness");
        if (!pbr) return;
        const std::string pkey = joinKey(key, "pbrMetallicRoughness");
        c.object(*pbr, pkey);
        c.optNumbers(*pbr, pkey, "baseColorFactor", 4);
        const json* texture = SchemaChecker::find(*pbr, "baseColorTexture");
        if (!texture) return;
        const std::string tkey = joinKey(pkey, "baseColorTexture");
        c.object(*texture, tkey);
        const json* index = SchemaChecker::find(*texture, "index");
        if (!index) c.fail(tkey, "no index");
        c.index(*index, tkey + ".index");
        c.optIndex(*texture, tkey, "texCoord");
    });
    c.eachObject(doc, "", "textures",
                 [&](const json& t, const std::string& key) { c.optIndex(t, key, "source"); });
    c.eachObject(doc, "", "images", [&](const json& i, const std::string& key) {
        c.optString(i, key, "uri");
        c.optString(i, key, "mimeType");
        c.optIndex(i, key, "bufferView");
    });
}

}  // namespace

void checkGltfJson(const json& doc, const std::string& label) {
    const SchemaChecker c(label);
    c.object(doc, "");
    const json* asset = SchemaChecker::find(doc, "asset");
    if (!asset) c.fail("asset", "missing (every glTF 2.0 file has asset.version)");
    c.object(*asset, "asset");
    const json* version = SchemaChecker::find(*asset, "version");
    if (!version) c.fail("asset.version", "missing");
    c.string(*version, "asset.version");
    const std::string v = version->get<std::string>();
    if (v.rfind("2.", 0) != 0) c.at(*version, "asset.version").expected("glTF version 2.x");
    if (const json* required = SchemaChecker::find(doc, "extensionsRequired")) {
        const std::size_t size = c.at(*required, "extensionsRequired").arraySize();
        for (std::size_t i = 0; i < size; ++i)
            c.string((*required)[i], "extensionsRequired." + std::to_string(i));
    }
    checkBuffers(c, doc);
    checkAccessors(c, doc);
    checkMeshes(c, doc);
    checkNodes(c, doc);
    checkMaterials(c, doc);
}

}  // namespace penumbra::scene
