// Built-in shapes: vertex and triangle counts, bounding boxes, unit outward normals and
// counter-clockwise winding seen from outside.
#include <gtest/gtest.h>

#include "renderer/scene/primitives.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

struct Bounds {
    glm::vec3 min{1e30f};
    glm::vec3 max{-1e30f};
};

Bounds boundsOf(const Mesh& mesh) {
    Bounds b;
    for (const glm::vec3& p : mesh.positions) {
        b.min = glm::min(b.min, p);
        b.max = glm::max(b.max, p);
    }
    return b;
}

// Structure every mesh must have, and for closed shapes around the origin, outward normals.
void expectWellFormed(const Mesh& mesh, bool closed) {
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    ASSERT_EQ(mesh.indices.size() % 3, 0u);
    for (std::uint32_t i : mesh.indices) ASSERT_LT(i, mesh.positions.size());
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        EXPECT_NEAR(glm::length(mesh.normals[v]), 1.0f, 1e-5f);
        if (closed) {
            EXPECT_GT(glm::dot(mesh.normals[v], mesh.positions[v]), 0.0f) << "vertex " << v;
        }
    }
    for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
        const glm::vec3 a = mesh.positions[mesh.indices[t]];
        const glm::vec3 b = mesh.positions[mesh.indices[t + 1]];
        const glm::vec3 c = mesh.positions[mesh.indices[t + 2]];
        const glm::vec3 face = glm::cross(b - a, c - a);
        ASSERT_GT(glm::length(face), 0.0f) << "degenerate triangle " << t / 3;
        const glm::vec3 n = mesh.normals[mesh.indices[t]] + mesh.normals[mesh.indices[t + 1]] +
                            mesh.normals[mesh.indices[t + 2]];
        EXPECT_GT(glm::dot(face, n), 0.0f) << "triangle " << t / 3 << " is wound clockwise";
    }
}

TEST(Primitives, PlaneLiesInXZFacingUp) {
    const Mesh mesh = makePlane({4, 2});
    expectWellFormed(mesh, false);
    EXPECT_EQ(mesh.positions.size(), 4u);
    EXPECT_EQ(mesh.indices.size(), 6u);
    for (const glm::vec3& n : mesh.normals) EXPECT_EQ(n, glm::vec3(0, 1, 0));
    const Bounds b = boundsOf(mesh);
    EXPECT_EQ(b.min, glm::vec3(-2, 0, -1));
    EXPECT_EQ(b.max, glm::vec3(2, 0, 1));
}

TEST(Primitives, BoxHasFlatOutwardFaces) {
    const Mesh mesh = makeBox({1, 2, 3});
    expectWellFormed(mesh, true);
    EXPECT_EQ(mesh.positions.size(), 24u);
    EXPECT_EQ(mesh.indices.size(), 36u);
    const Bounds b = boundsOf(mesh);
    EXPECT_EQ(b.min, glm::vec3(-0.5f, -1, -1.5f));
    EXPECT_EQ(b.max, glm::vec3(0.5f, 1, 1.5f));
    // Flat faces: each vertex's normal is a unit axis.
    for (const glm::vec3& n : mesh.normals)
        EXPECT_EQ(glm::abs(n.x) + glm::abs(n.y) + glm::abs(n.z), 1.0f);
}

TEST(Primitives, SphereCountsAndRadius) {
    for (int segments : {3, 4, 7, 32, 64}) {
        SCOPED_TRACE(segments);
        const Mesh mesh = makeSphere(0.75f, segments);
        expectWellFormed(mesh, true);
        const auto rings = static_cast<std::size_t>(std::max(2, segments / 2));
        const auto s = static_cast<std::size_t>(segments);
        EXPECT_EQ(mesh.positions.size(), (rings + 1) * (s + 1));
        EXPECT_EQ(mesh.indices.size() / 3, s * (2 * rings - 2));
        for (const glm::vec3& p : mesh.positions) EXPECT_NEAR(glm::length(p), 0.75f, 1e-5f);
        const Bounds b = boundsOf(mesh);
        EXPECT_NEAR(b.max.y, 0.75f, 1e-6f);
        EXPECT_NEAR(b.min.y, -0.75f, 1e-6f);
    }
}

TEST(Primitives, SceneObjectsCarryTheirShapes) {
    nlohmann::json doc = test::minimalScene();
    doc["objects"].push_back({{"box", {{"size", {1, 2, 3}}}}});
    doc["objects"][1]["sphere"]["segments"] = 8;
    const Scene scene = test::loadDoc(doc).at(0);
    const Mesh& plane = scene.objects[0].model->meshes.at(0);
    EXPECT_EQ(boundsOf(plane).max, glm::vec3(4, 0, 4));
    const Mesh& sphere = scene.objects[1].model->meshes.at(0);
    EXPECT_EQ(sphere.positions.size(), 5u * 9u);
    EXPECT_EQ(scene.objects[1].model->source, "sphere");
    const Mesh& box = scene.objects[2].model->meshes.at(0);
    EXPECT_EQ(boundsOf(box).max, glm::vec3(0.5f, 1, 1.5f));
    EXPECT_EQ(scene.objects[2].model->source, "box");
}

}  // namespace
}  // namespace penumbra::scene
