// Draco decoding of glTF primitives (Debian's libdraco): faces and the POSITION, NORMAL and
// TEXCOORD_0 attributes, each looked up by the unique id the glTF names.
#include "renderer/scene/gltf_draco.h"

#include <draco/compression/decode.h>

namespace penumbra::scene {
namespace {

template <int N>
std::vector<glm::vec<N, float>> readAttribute(const GltfDocument& doc, const draco::Mesh& mesh,
                                              const DracoReference& ref, const std::string& name,
                                              const std::string& key, bool required) {
    std::vector<glm::vec<N, float>> out;
    const auto id = ref.attributes.find(name);
    if (id == ref.attributes.end()) {
        if (required) doc.fail(key + ".attributes", "the Draco extension has no " + name);
        return out;
    }
    const std::string akey = key + ".extensions.KHR_draco_mesh_compression.attributes." + name;
    const draco::PointAttribute* attribute =
        mesh.GetAttributeByUniqueId(static_cast<std::uint32_t>(id->second));
    if (!attribute)
        doc.fail(akey, "no attribute with unique id " + std::to_string(id->second) +
                           " in the Draco data");
    if (attribute->num_components() < N)
        doc.fail(akey, "has " + std::to_string(attribute->num_components()) +
                           " components, expected " + std::to_string(N));
    out.resize(mesh.num_points());
    float value[4] = {0, 0, 0, 0};
    for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
        const draco::AttributeValueIndex v = attribute->mapped_index(p);
        if (v.value() >= attribute->size() ||
            !attribute->ConvertValue<float>(v, static_cast<std::int8_t>(N), value))
            doc.fail(akey, "cannot read value of point " + std::to_string(p.value()));
        for (int c = 0; c < N; ++c) out[p.value()][c] = value[c];
    }
    return out;
}

}  // namespace

DracoGeometry decodeDraco(const GltfDocument& doc, const DracoReference& ref,
                          const std::string& key, std::size_t max_triangles) {
    const std::string ekey = key + ".extensions.KHR_draco_mesh_compression";
    const auto& views = doc.model.bufferViews;
    if (ref.buffer_view < 0 || static_cast<std::size_t>(ref.buffer_view) >= views.size())
        doc.fail(ekey + ".bufferView",
                 "bufferView " + std::to_string(ref.buffer_view) + " does not exist");
    const tinygltf::BufferView& view = views[static_cast<std::size_t>(ref.buffer_view)];
    if (view.buffer < 0 || static_cast<std::size_t>(view.buffer) >= doc.model.buffers.size())
        doc.fail(ekey + ".bufferView", "its buffer does not exist");
    const auto& data = doc.model.buffers[static_cast<std::size_t>(view.buffer)].data;
    if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
        doc.fail(ekey + ".bufferView", "runs past the end of its buffer");

    draco::DecoderBuffer buffer;
    buffer.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
    draco::Decoder decoder;
    auto decoded = decoder.DecodeMeshFromBuffer(&buffer);
    if (!decoded.ok())
        doc.fail(ekey, "Draco decoding failed: " + decoded.status().error_msg_string());
    const std::unique_ptr<draco::Mesh>& mesh = decoded.value();
    if (!mesh) doc.fail(ekey, "Draco decoding failed");
    if (mesh->num_faces() > max_triangles)
        doc.fail(ekey, std::to_string(mesh->num_faces()) + " triangles, more than the limit of " +
                           std::to_string(max_triangles));

    DracoGeometry out;
    out.positions = readAttribute<3>(doc, *mesh, ref, "POSITION", key, true);
    out.normals = readAttribute<3>(doc, *mesh, ref, "NORMAL", key, false);
    out.uvs = readAttribute<2>(doc, *mesh, ref, "TEXCOORD_0", key, false);
    out.indices.reserve(static_cast<std::size_t>(mesh->num_faces()) * 3);
    for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
        for (const draco::PointIndex& p : mesh->face(f)) {
            if (p.value() >= mesh->num_points())
                doc.fail(ekey, "face " + std::to_string(f.value()) + " names point " +
                                   std::to_string(p.value()) + " of " +
                                   std::to_string(mesh->num_points()));
            out.indices.push_back(p.value());
        }
    }
    return out;
}

}  // namespace penumbra::scene
