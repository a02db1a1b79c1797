// glTF loading of valid files: node hierarchy and TRS baking, primitive modes, normals, sparse
// accessors, textures, scene selection and Draco.
#include <gtest/gtest.h>

#include <stb_image_write.h>

#include "gltf_builder.h"
#include "renderer/scene/gltf_loader.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;
using test::expectMessage;
using test::expectNear;
using test::GltfBuilder;
using test::inputErrorOf;

glm::vec3 faceNormal(const Mesh& mesh, std::size_t triangle) {
    const glm::vec3 a = mesh.positions[mesh.indices[triangle * 3]];
    const glm::vec3 b = mesh.positions[mesh.indices[triangle * 3 + 1]];
    const glm::vec3 c = mesh.positions[mesh.indices[triangle * 3 + 2]];
    return glm::normalize(glm::cross(b - a, c - a));
}

std::size_t triangleCount(const Model& model) {
    std::size_t n = 0;
    for (const Mesh& m : model.meshes) n += m.indices.size() / 3;
    return n;
}

void expectBounds(const Model& model, const glm::vec3& min, const glm::vec3& max, float tolerance) {
    glm::vec3 lo(1e30f);
    glm::vec3 hi(-1e30f);
    for (const Mesh& m : model.meshes)
        for (const glm::vec3& p : m.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    expectNear(lo, min, tolerance);
    expectNear(hi, max, tolerance);
}

TEST(GltfLoader, BakesTheNodeHierarchy) {
    // nodes.gltf: parent translated by (10, 0, 0) with two children drawing one triangle
    // ((0,0,0), (1,0,0), (0,1,0), no normals): one turned 90 degrees about Z and scaled by 2, one
    // mirrored in X by its matrix and moved up 5.
    const auto model = loadGltf(test::dataDir() / "nodes.gltf");
    ASSERT_EQ(model->meshes.size(), 2u);
    const Mesh& turned = model->meshes[0];
    expectNear(turned.positions[0], {10, 0, 0});
    expectNear(turned.positions[1], {10, 2, 0});
    expectNear(turned.positions[2], {8, 0, 0});
    const Mesh& mirrored = model->meshes[1];
    expectNear(mirrored.positions[0], {10, 5, 0});
    expectNear(mirrored.positions[1], {9, 5, 0});
    expectNear(mirrored.positions[2], {10, 6, 0});
    for (const Mesh* mesh : {&turned, &mirrored}) {
        ASSERT_EQ(mesh->indices.size(), 3u);
        for (const glm::vec3& n : mesh->normals) expectNear(n, {0, 0, 1});  // computed, then baked
        expectNear(faceNormal(*mesh, 0), {0, 0, 1});  // the mirror keeps front faces CCW
    }
    ASSERT_EQ(model->materials.size(), 1u);
    EXPECT_EQ(model->materials[0].base_color, glm::vec4(0.5f, 0.5f, 1.0f, 1.0f));
    EXPECT_EQ(model->materials[0].texture, -1);
    EXPECT_EQ(model->source, (test::dataDir() / "nodes.gltf").string());
}

TEST(GltfLoader, QuadAsGltfAndGlbIsTheSame) {
    const GltfBuilder quad = GltfBuilder::quad();
    for (const auto& path : {quad.writeGltf("quad"), quad.writeGlb("quad")}) {
        SCOPED_TRACE(path);
        const auto model = loadGltf(path);
        ASSERT_EQ(model->meshes.size(), 1u);
        const Mesh& mesh = model->meshes[0];
        EXPECT_EQ(mesh.positions.size(), 4u);
        EXPECT_EQ(mesh.indices, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3}));
        EXPECT_EQ(mesh.uvs.at(2), glm::vec2(1, 0));
        EXPECT_EQ(mesh.normals.at(3), glm::vec3(0, 0, 1));
        EXPECT_EQ(model->materials.size(), 1u);  // the default material
        EXPECT_EQ(model->materials[0].base_color, glm::vec4(1.0f));
    }
}

TEST(GltfLoader, StripsAndFansBecomeTriangles) {
    const glm::vec3 square[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    struct Case {
        int mode;
        std::vector<std::uint16_t> indices;
    };
    // Strip 0 1 2 3 covers the square; fan 0 1 3 2 covers it too. Both face +Z.
    for (const Case& c :
         {Case{5, {0, 1, 2, 3}}, Case{6, {0, 1, 3, 2}}, Case{4, {0, 1, 2, 2, 1, 3}}}) {
        SCOPED_TRACE(c.mode);
        GltfBuilder b = GltfBuilder::quad();
        std::vector<float> p;
        for (const glm::vec3& v : square) p.insert(p.end(), {v.x, v.y, v.z});
        b.doc["meshes"][0]["primitives"][0] = {
            {"attributes", {{"POSITION", b.floats(p, "VEC3", 3)}}},
            {"indices",
             b.accessor(b.view(test::bytesOf(c.indices)), 5123, c.indices.size(), "SCALAR")},
            {"mode", c.mode}};
        const auto model = loadGltf(b.writeGltf("mode" + std::to_string(c.mode)));
        const Mesh& mesh = model->meshes.at(0);
        ASSERT_EQ(mesh.indices.size(), 6u);
        for (std::size_t t = 0; t < 2; ++t) expectNear(faceNormal(mesh, t), {0, 0, 1});
        for (const glm::vec3& n : mesh.normals) expectNear(n, {0, 0, 1});
    }
}

TEST(GltfLoader, AssetGeneratorPrimitiveModes) {
    const auto dir = test::assimpGltfDir() / "glTF-Asset-Generator/Mesh_PrimitiveMode";
    if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " not installed";
    // Triangles, strips and fans (indexed or not) draw the same square.
    for (int i : {4, 5, 6, 11, 12, 13, 14, 15}) {
        char name[64];
        std::snprintf(name, sizeof name, "Mesh_PrimitiveMode_%02d.gltf", i);
        SCOPED_TRACE(name);
        const auto model = loadGltf(dir / name);
        ASSERT_EQ(triangleCount(*model), 2u);
        const Mesh& mesh = model->meshes.at(0);
        const glm::vec3 first = faceNormal(mesh, 0);
        expectNear(faceNormal(mesh, 1), first);
        expectNear(mesh.normals.at(0), first);
    }
    // Points and lines draw no surface.
    for (int i : {0, 1, 2, 3, 7, 8, 9, 10}) {
        char name[64];
        std::snprintf(name, sizeof name, "Mesh_PrimitiveMode_%02d.gltf", i);
        SCOPED_TRACE(name);
        expectMessage(inputErrorOf([&] { loadGltf(dir / name); }),
                      "meshes.0.primitives.0.mode: unsupported primitive mode");
    }
}

TEST(GltfLoader, MissingAndZeroNormalsAreComputed) {
    GltfBuilder b = GltfBuilder::quad();
    b.doc["accessors"][1]["bufferView"] = b.view(test::bytesOf(std::vector<float>(12, 0.0f)));
    const Mesh zero = loadGltf(b.writeGltf("zero-normals"))->meshes.at(0);
    for (const glm::vec3& n : zero.normals) expectNear(n, {0, 0, 1});
    b.doc["meshes"][0]["primitives"][0]["attributes"].erase("NORMAL");
    const Mesh none = loadGltf(b.writeGltf("no-normals"))->meshes.at(0);
    for (const glm::vec3& n : none.normals) expectNear(n, {0, 0, 1});
}

TEST(GltfLoader, SceneSelection) {
    GltfBuilder b = GltfBuilder::quad();
    b.doc["nodes"] = {{{"mesh", 0}}, {{"mesh", 0}, {"translation", {0, 0, 5}}}};
    b.doc["scenes"] = {{{"nodes", {0}}}, {{"nodes", {1}}}};
    b.doc["scene"] = 1;
    EXPECT_EQ(loadGltf(b.writeGltf("scene1"))->meshes.at(0).positions.at(0), glm::vec3(0, 0, 5));
    b.doc.erase("scene");  // no default: scene 0
    EXPECT_EQ(loadGltf(b.writeGltf("scene0"))->meshes.at(0).positions.at(0), glm::vec3(0, 0, 0));
    b.doc.erase("scenes");  // no scenes: every root node
    EXPECT_EQ(loadGltf(b.writeGltf("roots"))->meshes.size(), 2u);
}

TEST(GltfLoader, SparseAccessorsAndNormalizedTexcoords) {
    GltfBuilder b = GltfBuilder::quad();
    // Sparse: vertex 2 of POSITION moved to (2, 2, 0).
    const int indices = b.view(test::bytesOf(std::vector<std::uint8_t>{2, 0, 0, 0}));
    const int values = b.view(test::bytesOf(std::vector<float>{2, 2, 0}));
    b.doc["accessors"][0]["sparse"] = {
        {"count", 1},
        {"indices", {{"bufferView", indices}, {"componentType", 5121}}},
        {"values", {{"bufferView", values}}}};
    // TEXCOORD_0 as normalized unsigned bytes.
    const int uv =
        b.accessor(b.view(test::bytesOf(std::vector<std::uint8_t>{0, 255, 255, 255, 255, 0, 0, 0})),
                   5121, 4, "VEC2");
    b.doc["accessors"][uv]["normalized"] = true;
    b.doc["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"] = uv;
    const Mesh mesh = loadGltf(b.writeGltf("sparse"))->meshes.at(0);
    EXPECT_EQ(mesh.positions.at(2), glm::vec3(2, 2, 0));
    EXPECT_EQ(mesh.positions.at(1), glm::vec3(1, 0, 0));
    EXPECT_EQ(mesh.uvs.at(0), glm::vec2(0, 1));
    EXPECT_EQ(mesh.uvs.at(2), glm::vec2(1, 0));
}

TEST(GltfLoader, EmbeddedPngTexture) {
    // A 2x1 RGBA image: red, then half-transparent blue.
    const unsigned char pixels[] = {255, 0, 0, 255, 0, 0, 255, 128};
    std::string png;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                       static_cast<std::size_t>(size));
        },
        &png, 2, 1, 4, pixels, 8);
    GltfBuilder b = GltfBuilder::quad();
    b.doc["images"] = {{{"bufferView", b.view(png)}, {"mimeType", "image/png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    b.doc["materials"] = {
        {{"pbrMetallicRoughness",
          {{"baseColorFactor", {1, 0.5, 1, 1}}, {"baseColorTexture", {{"index", 0}}}}}}};
    b.doc["meshes"][0]["primitives"][0]["material"] = 0;
    for (const auto& path : {b.writeGltf("textured"), b.writeGlb("textured")}) {
        const auto model = loadGltf(path);
        ASSERT_EQ(model->textures.size(), 1u);
        EXPECT_EQ(model->textures[0].width, 2);
        EXPECT_EQ(model->textures[0].height, 1);
        EXPECT_EQ(model->textures[0].rgba, std::vector<std::uint8_t>(pixels, pixels + 8));
        EXPECT_EQ(model->materials.at(0).texture, 0);
        EXPECT_EQ(model->materials.at(0).base_color, glm::vec4(1, 0.5f, 1, 1));
    }
}

TEST(GltfLoader, AssimpBoxTexturedInEveryPackaging) {
    const auto dir = test::assimpGltfDir();
    if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " not installed";
    const auto reference = loadGltf(dir / "BoxTextured-glTF/BoxTextured.gltf");
    ASSERT_EQ(reference->meshes.size(), 1u);
    const Mesh& mesh = reference->meshes[0];
    EXPECT_EQ(mesh.positions.size(), 24u);
    EXPECT_EQ(mesh.indices.size(), 36u);
    EXPECT_EQ(mesh.uvs.size(), 24u);
    // The root node turns the box by -90 degrees about X: still the unit cube, normals outward.
    expectBounds(*reference, glm::vec3(-0.5f), glm::vec3(0.5f), 1e-5f);
    for (std::size_t v = 0; v < mesh.positions.size(); ++v)
        EXPECT_GT(glm::dot(mesh.normals[v], mesh.positions[v]), 0.0f);
    for (std::size_t t = 0; t < 12; ++t)
        EXPECT_GT(glm::dot(faceNormal(mesh, t), mesh.normals[mesh.indices[t * 3]]), 0.9f);
    ASSERT_EQ(reference->textures.size(), 1u);
    EXPECT_EQ(reference->textures[0].width, 211);
    EXPECT_EQ(reference->textures[0].height, 211);
    EXPECT_EQ(reference->textures[0].rgba.size(), 211u * 211u * 4u);
    EXPECT_EQ(reference->materials.at(mesh.material).texture, 0);

    for (const char* other : {"BoxTextured-glTF-Binary/BoxTextured.glb",
                              "BoxTextured-glTF-Embedded/BoxTextured.gltf"}) {
        SCOPED_TRACE(other);
        const auto model = loadGltf(dir / other);
        ASSERT_EQ(model->meshes.size(), 1u);
        EXPECT_EQ(model->meshes[0].positions, mesh.positions);
        EXPECT_EQ(model->meshes[0].indices, mesh.indices);
        EXPECT_EQ(model->meshes[0].uvs, mesh.uvs);
        ASSERT_EQ(model->textures.size(), 1u);
        EXPECT_EQ(model->textures[0].rgba, reference->textures[0].rgba);
    }
}

TEST(GltfLoader, DracoMatchesTheUncompressedFile) {
    const auto dir = test::assimpGltfDir();
    if (!std::filesystem::exists(dir / "draco")) GTEST_SKIP() << "assimp test models not installed";
    const auto draco = loadGltf(dir / "draco/2CylinderEngine.gltf");
    const auto plain = loadGltf(dir / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    EXPECT_GT(triangleCount(*draco), 100000u);
    // Draco's encoder drops a few degenerate faces (110336 against 110342 here).
    EXPECT_NEAR(static_cast<double>(triangleCount(*draco)),
                static_cast<double>(triangleCount(*plain)),
                1e-3 * static_cast<double>(triangleCount(*plain)));
    EXPECT_EQ(draco->meshes.size(), plain->meshes.size());
    // Draco quantises positions: compare bounds to a small fraction of the engine's size.
    glm::vec3 lo(1e30f), hi(-1e30f);
    for (const Mesh& m : plain->meshes)
        for (const glm::vec3& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
    expectBounds(*draco, lo, hi, 0.01f * glm::length(hi - lo));
}

}  // namespace
}  // namespace penumbra::scene
