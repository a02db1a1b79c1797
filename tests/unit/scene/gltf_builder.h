// Test helper: builds small glTF documents in memory (one buffer, views appended to it) and
// writes them as .gltf with a data URI or as .glb, so each test case can break one thing.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene_test_support.h"

namespace penumbra::scene::test {

inline std::string base64(const std::string& bytes) {
    static const char* const kAlphabet =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < bytes.size(); i += 3) {
        const unsigned v = (static_cast<unsigned char>(bytes[i]) << 16) |
                           (static_cast<unsigned char>(bytes[i + 1]) << 8) |
                           static_cast<unsigned char>(bytes[i + 2]);
        for (int s = 18; s >= 0; s -= 6) out += kAlphabet[(v >> s) & 63];
    }
    if (i < bytes.size()) {
        unsigned v = static_cast<unsigned char>(bytes[i]) << 16;
        if (i + 1 < bytes.size()) v |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += i + 1 < bytes.size() ? kAlphabet[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

template <typename T>
std::string bytesOf(const std::vector<T>& values) {
    std::string out(values.size() * sizeof(T), '\0');
    std::memcpy(out.data(), values.data(), out.size());
    return out;
}

class GltfBuilder {
public:
    GltfBuilder() {
        doc = {{"asset", {{"version", "2.0"}}},
               {"bufferViews", nlohmann::json::array()},
               {"accessors", nlohmann::json::array()}};
    }

    // Appends BYTES (4-byte aligned) as a new bufferView; returns its index.
    int view(const std::string& bytes, int stride = 0) {
        bin_.resize((bin_.size() + 3) / 4 * 4, '\0');
        nlohmann::json v = {
            {"buffer", 0}, {"byteOffset", bin_.size()}, {"byteLength", bytes.size()}};
        if (stride) v["byteStride"] = stride;
        bin_ += bytes;
        doc["bufferViews"].push_back(v);
        return static_cast<int>(doc["bufferViews"].size() - 1);
    }

    int accessor(int view_index, int component_type, std::size_t count, const char* type) {
        doc["accessors"].push_back({{"bufferView", view_index},
                                    {"componentType", component_type},
                                    {"count", count},
                                    {"type", type}});
        return static_cast<int>(doc["accessors"].size() - 1);
    }

    int floats(const std::vector<float>& values, const char* type, std::size_t components) {
        return accessor(view(bytesOf(values)), 5126, values.size() / components, type);
    }

    // A unit quad in the XY plane facing +Z: 4 vertices with normals and uvs, 2 triangles, one
    // node, one scene.
    static GltfBuilder quad() {
        GltfBuilder b;
        const int position = b.floats({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, "VEC3", 3);
        const int normal = b.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
        const int uv = b.floats({0, 1, 1, 1, 1, 0, 0, 0}, "VEC2", 2);
        const int indices = b.accessor(
            b.view(bytesOf(std::vector<std::uint16_t>{0, 1, 2, 0, 2, 3})), 5123, 6, "SCALAR");
        b.doc["meshes"] = {
            {{"primitives",
              {{{"attributes", {{"POSITION", position}, {"NORMAL", normal}, {"TEXCOORD_0", uv}}},
                {"indices", indices}}}}}};
        b.doc["nodes"] = {{{"mesh", 0}}};
        b.doc["scenes"] = {{{"nodes", {0}}}};
        b.doc["scene"] = 0;
        return b;
    }

    // Writes NAME.gltf into the scratch folder with the buffer as a data URI.
    std::filesystem::path writeGltf(const std::string& name) const {
        nlohmann::json out = doc;
        if (!out.contains("buffers"))
            out["buffers"] = {{{"byteLength", bin_.size()},
                               {"uri", "data:application/octet-stream;base64," + base64(bin_)}}};
        return writeFile(name + ".gltf", out.dump(1));
    }

    // Writes NAME.glb into the scratch folder with the buffer as its BIN chunk.
    std::filesystem::path writeGlb(const std::string& name) const {
        nlohmann::json out = doc;
        if (!out.contains("buffers")) out["buffers"] = {{{"byteLength", bin_.size()}}};
        std::string json = out.dump();
        json.resize((json.size() + 3) / 4 * 4, ' ');
        std::string bin = bin_;
        bin.resize((bin.size() + 3) / 4 * 4, '\0');
        std::string glb;
        auto u32 = [&](std::uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
        u32(0x46546C67);
        u32(2);
        u32(static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
        u32(static_cast<std::uint32_t>(json.size()));
        u32(0x4E4F534A);
        glb += json;
        u32(static_cast<std::uint32_t>(bin.size()));
        u32(0x004E4942);
        glb += bin;
        return writeFile(name + ".glb", glb);
    }

    // Overwrites bytes of the buffer at OFFSET (to corrupt data after building).
    void poke(std::size_t offset, const std::string& bytes) {
        bin_.replace(offset, bytes.size(), bytes);
    }
    std::size_t viewOffset(int index) const {
        return doc["bufferViews"][index]["byteOffset"].get<std::size_t>();
    }

    nlohmann::json doc;

private:
    std::string bin_;
};

}  // namespace penumbra::scene::test
