// glTF primitives to triangles: modes converted, attribute counts and index ranges checked,
// values required finite, normals normalised or computed.
#include "renderer/scene/gltf_primitive.h"

#include <cmath>
#include <string>

#include "renderer/scene/gltf_accessor.h"
#include "renderer/scene/gltf_draco.h"

namespace penumbra::scene {
namespace {

std::string primitiveKey(int mesh, int primitive) {
    return "meshes." + std::to_string(mesh) + ".primitives." + std::to_string(primitive);
}

const tinygltf::Primitive& primitiveAt(const GltfDocument& doc, int mesh, int primitive) {
    return doc.model.meshes[static_cast<std::size_t>(mesh)]
        .primitives[static_cast<std::size_t>(primitive)];
}

// Checks the primitive's mode: only the three triangle modes draw surfaces.
void checkMode(const GltfDocument& doc, int mode, const std::string& key) {
    static const char* const kNames[] = {"POINTS", "LINES", "LINE_LOOP", "LINE_STRIP"};
    if (mode >= 0 && mode <= 3)
        doc.fail(key + ".mode", "unsupported primitive mode " + std::to_string(mode) + " (" +
                                    kNames[mode] +
                                    "; only triangles, strips and fans draw surfaces)");
    if (mode < 4 || mode > 6)
        doc.fail(key + ".mode", "invalid primitive mode " + std::to_string(mode));
}

std::size_t trianglesFor(int mode, std::size_t count) {
    if (mode == TINYGLTF_MODE_TRIANGLES) return count / 3;
    return count >= 3 ? count - 2 : 0;
}

// Triangle list from an index list in MODE, dropping triangles that repeat a vertex.
std::vector<std::uint32_t> triangulate(int mode, const std::vector<std::uint32_t>& in) {
    std::vector<std::uint32_t> out;
    out.reserve(trianglesFor(mode, in.size()) * 3);
    auto emit = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        if (a != b && b != c && a != c) out.insert(out.end(), {a, b, c});
    };
    const std::size_t n = in.size();
    if (mode == TINYGLTF_MODE_TRIANGLES) {
        for (std::size_t i = 0; i + 2 < n; i += 3) emit(in[i], in[i + 1], in[i + 2]);
    } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
        // Every other triangle of a strip is wound the other way round.
        for (std::size_t i = 0; i + 2 < n; ++i) {
            if (i % 2 == 0)
                emit(in[i], in[i + 1], in[i + 2]);
            else
                emit(in[i + 1], in[i], in[i + 2]);
        }
    } else {
        for (std::size_t i = 1; i + 1 < n; ++i) emit(in[0], in[i], in[i + 1]);
    }
    return out;
}

template <typename Vec>
void checkFinite(const GltfDocument& doc, const std::vector<Vec>& values, const std::string& key) {
    for (std::size_t i = 0; i < values.size(); ++i)
        for (int c = 0; c < Vec::length(); ++c)
            if (!std::isfinite(values[i][c]))
                doc.fail(key, "non-finite value at vertex " + std::to_string(i));
}

void checkCount(const GltfDocument& doc, std::size_t count, std::size_t vertices,
                const std::string& key) {
    if (count != vertices)
        doc.fail(key,
                 std::to_string(count) + " values, but POSITION has " + std::to_string(vertices));
}

// Unit normals: given ones normalised, zero-length ones replaced by smooth normals.
void finishNormals(const GltfDocument& doc, PrimitiveGeometry& g, const std::string& key) {
    if (g.normals.empty()) {
        g.normals = smoothNormals(g.positions, g.indices);
        return;
    }
    checkFinite(doc, g.normals, key + ".attributes.NORMAL");
    std::vector<glm::vec3> smooth;
    for (std::size_t i = 0; i < g.normals.size(); ++i) {
        const float length = glm::length(g.normals[i]);
        if (length > 1e-12f && std::isfinite(length)) {
            g.normals[i] /= length;
            continue;
        }
        if (smooth.empty()) smooth = smoothNormals(g.positions, g.indices);
        g.normals[i] = smooth[i];
    }
}

}  // namespace

std::vector<glm::vec3> smoothNormals(const std::vector<glm::vec3>& positions,
                                     const std::vector<std::uint32_t>& triangles) {
    std::vector<glm::dvec3> sum(positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
        const glm::dvec3 a(positions[triangles[t]]);
        const glm::dvec3 b(positions[triangles[t + 1]]);
        const glm::dvec3 c(positions[triangles[t + 2]]);
        const glm::dvec3 n = glm::cross(b - a, c - a);  // length = twice the area
        for (std::size_t k = 0; k < 3; ++k) sum[triangles[t + k]] += n;
    }
    std::vector<glm::vec3> normals(positions.size());
    for (std::size_t i = 0; i < sum.size(); ++i) {
        const double length = glm::length(sum[i]);
        normals[i] =
            length > 0.0 && std::isfinite(length) ? glm::vec3(sum[i] / length) : glm::vec3(0, 1, 0);
    }
    return normals;
}

PrimitiveSize primitiveSize(const GltfDocument& doc, int mesh, int primitive) {
    const std::string key = primitiveKey(mesh, primitive);
    const tinygltf::Primitive& p = primitiveAt(doc, mesh, primitive);
    checkMode(doc, p.mode, key);
    const auto position = p.attributes.find("POSITION");
    if (position == p.attributes.end()) doc.fail(key + ".attributes", "no POSITION");
    PrimitiveSize size;
    size.vertices = accessorAt(doc, position->second, key + ".attributes.POSITION").count;
    std::size_t count = size.vertices;
    const auto draco = doc.draco.find({mesh, primitive});
    const int indices = draco != doc.draco.end() ? draco->second.indices : p.indices;
    if (indices >= 0) count = accessorAt(doc, indices, key + ".indices").count;
    size.triangles = trianglesFor(p.mode, count);
    return size;
}

PrimitiveGeometry readPrimitive(const GltfDocument& doc, int mesh, int primitive,
                                std::size_t max_triangles) {
    const std::string key = primitiveKey(mesh, primitive);
    const tinygltf::Primitive& p = primitiveAt(doc, mesh, primitive);
    checkMode(doc, p.mode, key);
    PrimitiveGeometry g;
    std::vector<std::uint32_t> indices;
    int mode = p.mode;
    const auto draco = doc.draco.find({mesh, primitive});
    if (draco != doc.draco.end()) {
        if (mode != TINYGLTF_MODE_TRIANGLES)
            doc.fail(key + ".mode", "Draco-compressed primitives must be TRIANGLES");
        DracoGeometry d = decodeDraco(doc, draco->second, key, max_triangles);
        g.positions = std::move(d.positions);
        g.normals = std::move(d.normals);
        g.uvs = std::move(d.uvs);
        indices = std::move(d.indices);
    } else {
        const auto attribute = [&](const char* name) {
            const auto it = p.attributes.find(name);
            return it == p.attributes.end() ? -1 : it->second;
        };
        const int position = attribute("POSITION");
        if (position < 0) doc.fail(key + ".attributes", "no POSITION");
        g.positions = readVec3(doc, position, key + ".attributes.POSITION");
        if (const int normal = attribute("NORMAL"); normal >= 0) {
            g.normals = readVec3(doc, normal, key + ".attributes.NORMAL");
            checkCount(doc, g.normals.size(), g.positions.size(), key + ".attributes.NORMAL");
        }
        if (const int uv = attribute("TEXCOORD_0"); uv >= 0) {
            g.uvs = readTexcoords(doc, uv, key + ".attributes.TEXCOORD_0");
            checkCount(doc, g.uvs.size(), g.positions.size(), key + ".attributes.TEXCOORD_0");
        }
        if (p.indices >= 0) {
            indices = readIndices(doc, p.indices, key + ".indices");
        } else {
            indices.reserve(g.positions.size());
            for (std::size_t i = 0; i < g.positions.size(); ++i)
                indices.push_back(static_cast<std::uint32_t>(i));
        }
    }
    checkFinite(doc, g.positions, key + ".attributes.POSITION");
    checkFinite(doc, g.uvs, key + ".attributes.TEXCOORD_0");
    for (std::uint32_t index : indices)
        if (index >= g.positions.size())
            doc.fail(key + ".indices", "index " + std::to_string(index) + " out of range (" +
                                           std::to_string(g.positions.size()) + " vertices)");
    if (mode == TINYGLTF_MODE_TRIANGLES && indices.size() % 3 != 0)
        doc.fail(p.indices >= 0 ? key + ".indices" : key + ".attributes.POSITION",
                 "count " + std::to_string(indices.size()) + " is not a multiple of 3");
    g.indices = triangulate(mode, indices);
    finishNormals(doc, g, key);
    return g;
}

}  // namespace penumbra::scene
