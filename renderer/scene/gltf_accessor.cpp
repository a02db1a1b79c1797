// Accessor reading: element type and component type checked against what the attribute needs,
// bufferView and buffer references checked, every byte read proven inside its buffer.
#include "renderer/scene/gltf_accessor.h"

#include <algorithm>

#include "renderer/scene/gltf_components.h"

namespace penumbra::scene {
namespace {

constexpr std::size_t kMaxAccessorElements = std::size_t{1} << 26;
// Elements an accessor without a bufferView may declare (zeros no byte of the file holds).
constexpr std::size_t kMaxZeroElements = std::size_t{1} << 16;

// What an attribute needs from its accessor.
struct Expected {
    int type;                                    // TINYGLTF_TYPE_*
    std::initializer_list<int> component_types;  // allowed
    bool integer_indices;                        // indices: unsigned, not normalized
    const char* description;
};

// The bytes of bufferView VIEW, checked against its buffer.
std::pair<const unsigned char*, std::size_t> viewBytes(const GltfDocument& doc, int view,
                                                       const std::string& key) {
    const auto& views = doc.model.bufferViews;
    if (view < 0 || static_cast<std::size_t>(view) >= views.size())
        doc.fail(key, "bufferView " + std::to_string(view) + " does not exist");
    const tinygltf::BufferView& v = views[static_cast<std::size_t>(view)];
    const auto& buffers = doc.model.buffers;
    if (v.buffer < 0 || static_cast<std::size_t>(v.buffer) >= buffers.size())
        doc.fail(key, "bufferViews." + std::to_string(view) + ": buffer " +
                          std::to_string(v.buffer) + " does not exist");
    const std::vector<unsigned char>& data = buffers[static_cast<std::size_t>(v.buffer)].data;
    if (v.byteOffset > data.size() || v.byteLength > data.size() - v.byteOffset)
        doc.fail(key, "bufferViews." + std::to_string(view) + " runs past the end of buffers." +
                          std::to_string(v.buffer) + " (" + std::to_string(data.size()) +
                          " bytes)");
    return {data.data() + v.byteOffset, v.byteLength};
}

// Reads accessor INDEX, calling STORE(element, component, value) for each value, sparse
// substitutions included (elements without data are left to the caller's zeros).
// ALLOCATE() is called once every check has passed, before the first STORE: a count that its
// buffer cannot hold is refused before anything is allocated for it.
template <typename Allocate, typename Store>
std::size_t readAccessor(const GltfDocument& doc, int index, const std::string& key,
                         const Expected& expected, Allocate allocate, Store store) {
    const tinygltf::Accessor& a = accessorAt(doc, index, key);
    const std::string where = "accessor " + std::to_string(index);
    bool allowed = false;
    for (int t : expected.component_types) allowed = allowed || a.componentType == t;
    if (a.type != expected.type || !allowed)
        doc.fail(key, where + ": expected " + expected.description + ", got " + typeName(a.type) +
                          " " + componentName(a.componentType) +
                          (a.normalized ? " normalized" : ""));
    const bool normalized = !expected.integer_indices && a.componentType != kFloat;
    if (normalized && !a.normalized)
        doc.fail(key, where + ": expected " + expected.description + ", got " +
                          componentName(a.componentType) + " not normalized");
    const int components = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
    const std::size_t size = componentSize(a.componentType);
    const std::size_t element = size * static_cast<std::size_t>(components);

    if (a.bufferView >= 0 && a.count > 0) {
        const auto [bytes, length] = viewBytes(doc, a.bufferView, key + " (" + where + ")");
        const std::size_t view_stride =
            doc.model.bufferViews[static_cast<std::size_t>(a.bufferView)].byteStride;
        if (view_stride != 0 && view_stride < element)
            doc.fail(key, where + ": bufferView byteStride " + std::to_string(view_stride) +
                              " is smaller than an element (" + std::to_string(element) +
                              " bytes)");
        const std::size_t stride = view_stride != 0 ? view_stride : element;
        const std::uint64_t end =
            std::uint64_t{a.byteOffset} + std::uint64_t{a.count - 1} * stride + element;
        if (end > length)
            doc.fail(key, where + ": needs " + std::to_string(end) + " bytes of bufferView " +
                              std::to_string(a.bufferView) + ", which has " +
                              std::to_string(length));
        allocate();
        for (std::size_t i = 0; i < a.count; ++i) {
            const unsigned char* p = bytes + a.byteOffset + i * stride;
            for (int c = 0; c < components; ++c)
                store(i, c,
                      decode(p + static_cast<std::size_t>(c) * size, a.componentType, normalized));
        }
    } else if (a.bufferView < -1) {
        doc.fail(key, where + ": bufferView " + std::to_string(a.bufferView) + " does not exist");
    }

    if (!a.sparse.isSparse) {
        allocate();
        return a.count;
    }
    const auto& sparse = a.sparse;
    const std::string skey = key + " (" + where + ".sparse)";
    if (sparse.count < 1 || static_cast<std::size_t>(sparse.count) > a.count)
        doc.fail(skey,
                 "count " + std::to_string(sparse.count) + " not in 1.." + std::to_string(a.count));
    const auto n = static_cast<std::size_t>(sparse.count);
    const int index_type = sparse.indices.componentType;
    if (index_type != kUByte && index_type != kUShort && index_type != kUInt)
        doc.fail(skey, "indices must be unsigned byte, short or int");
    const auto [ibytes, ilength] = viewBytes(doc, sparse.indices.bufferView, skey + ".indices");
    const auto [vbytes, vlength] = viewBytes(doc, sparse.values.bufferView, skey + ".values");
    const auto ioffset = static_cast<std::size_t>(std::max(0, sparse.indices.byteOffset));
    const auto voffset = static_cast<std::size_t>(std::max(0, sparse.values.byteOffset));
    const std::size_t isize = componentSize(index_type);
    if (std::uint64_t{ioffset} + std::uint64_t{n} * isize > ilength)
        doc.fail(skey, "indices run past the end of their bufferView");
    if (std::uint64_t{voffset} + std::uint64_t{n} * element > vlength)
        doc.fail(skey, "values run past the end of their bufferView");
    allocate();
    for (std::size_t k = 0; k < n; ++k) {
        const auto target =
            static_cast<std::size_t>(decode(ibytes + ioffset + k * isize, index_type, false));
        if (target >= a.count)
            doc.fail(skey, "index " + std::to_string(target) + " out of range (" +
                               std::to_string(a.count) + " elements)");
        const unsigned char* p = vbytes + voffset + k * element;
        for (int c = 0; c < components; ++c)
            store(target, c,
                  decode(p + static_cast<std::size_t>(c) * size, a.componentType, normalized));
    }
    return a.count;
}

}  // namespace

const tinygltf::Accessor& accessorAt(const GltfDocument& doc, int index, const std::string& key) {
    if (index < 0 || static_cast<std::size_t>(index) >= doc.model.accessors.size())
        doc.fail(key, "accessor " + std::to_string(index) + " does not exist");
    const tinygltf::Accessor& a = doc.model.accessors[static_cast<std::size_t>(index)];
    const std::string where = "accessor " + std::to_string(index);
    // Checked before anything is allocated for it: the count must be backed by bytes.
    if (a.count > kMaxAccessorElements)
        doc.fail(key, where + ": count " + std::to_string(a.count) + " too large (limit " +
                          std::to_string(kMaxAccessorElements) + ")");
    if (a.bufferView < 0 && a.count > kMaxZeroElements)
        doc.fail(key, where + ": declares " + std::to_string(a.count) +
                          " elements but has no bufferView (at most " +
                          std::to_string(kMaxZeroElements) + " zeros without one)");
    return a;
}

std::vector<glm::vec3> readVec3(const GltfDocument& doc, int index, const std::string& key) {
    const std::size_t count = accessorAt(doc, index, key).count;
    std::vector<glm::vec3> out;
    auto allocate = [&] {
        if (out.size() != count) out.assign(count, glm::vec3(0.0f));
    };
    readAccessor(doc, index, key, {TINYGLTF_TYPE_VEC3, {kFloat}, false, "VEC3 float"}, allocate,
                 [&](std::size_t i, int c, double v) { out[i][c] = static_cast<float>(v); });
    return out;
}

std::vector<glm::vec2> readTexcoords(const GltfDocument& doc, int index, const std::string& key) {
    const std::size_t count = accessorAt(doc, index, key).count;
    std::vector<glm::vec2> out;
    auto allocate = [&] {
        if (out.size() != count) out.assign(count, glm::vec2(0.0f));
    };
    readAccessor(doc, index, key,
                 {TINYGLTF_TYPE_VEC2,
                  {kFloat, kUByte, kUShort},
                  false,
                  "VEC2 float or normalized unsigned byte/short"},
                 allocate,
                 [&](std::size_t i, int c, double v) { out[i][c] = static_cast<float>(v); });
    return out;
}

std::vector<std::uint32_t> readIndices(const GltfDocument& doc, int index, const std::string& key) {
    const std::size_t count = accessorAt(doc, index, key).count;
    std::vector<std::uint32_t> out;
    auto allocate = [&] {
        if (out.size() != count) out.assign(count, 0u);
    };
    readAccessor(doc, index, key,
                 {TINYGLTF_TYPE_SCALAR,
                  {kUByte, kUShort, kUInt},
                  true,
                  "SCALAR unsigned byte, short or int"},
                 allocate,
                 [&](std::size_t i, int, double v) { out[i] = static_cast<std::uint32_t>(v); });
    return out;
}

}  // namespace penumbra::scene
