// Closed- and convex-surface tests: the built-in solids close and are convex, a plane and a box
// with a face missing or turned do not close, seams that repeat a position still close, and the
// duck, two boxes in one model and a box with a dent are not convex.
#include <gtest/gtest.h>

#include "renderer/scene/gltf_loader.h"
#include "renderer/scene/mesh_topology.h"
#include "renderer/scene/primitives.h"

namespace penumbra::scene {
namespace {

Model modelOf(std::vector<Mesh> meshes) {
    Model m;
    m.meshes = std::move(meshes);
    return m;
}

TEST(MeshTopology, TheBuiltInSolidsCloseAndThePlaneDoesNot) {
    EXPECT_TRUE(isClosedSurface(modelOf({makeBox({1, 2, 3})})));   // 24 vertices: seams welded
    EXPECT_TRUE(isClosedSurface(modelOf({makeSphere(0.5f, 3)})));  // pole triangles degenerate
    EXPECT_TRUE(isClosedSurface(modelOf({makeSphere(0.5f, 32)})));
    EXPECT_FALSE(isClosedSurface(modelOf({makePlane({1, 1})})));
    EXPECT_FALSE(isClosedSurface(modelOf({})));
    Mesh point = makeBox({0, 0, 0});  // every triangle without area
    EXPECT_FALSE(isClosedSurface(modelOf({point})));
}

TEST(MeshTopology, ABoxWithAFaceMissingOrTurnedIsOpen) {
    Mesh missing = makeBox({1, 1, 1});
    missing.indices.resize(missing.indices.size() - 6);
    EXPECT_FALSE(isClosedSurface(modelOf({missing})));

    Mesh turned = makeBox({1, 1, 1});
    const std::size_t n = turned.indices.size();
    std::swap(turned.indices[n - 1], turned.indices[n - 2]);
    std::swap(turned.indices[n - 4], turned.indices[n - 5]);
    EXPECT_FALSE(isClosedSurface(modelOf({turned})));
}

TEST(MeshTopology, TwoMeshesCloseTogether) {
    // A box split into two meshes (a glTF's two primitives): each alone is open.
    Mesh box = makeBox({1, 1, 1});
    Mesh half = box;
    half.indices.assign(box.indices.begin() + 18, box.indices.end());
    box.indices.resize(18);
    EXPECT_FALSE(isClosedSurface(modelOf({box})));
    EXPECT_TRUE(isClosedSurface(modelOf({box, half})));
}

TEST(MeshTopology, TheDuckCloses) {
    // Its seams repeat positions with other normals and uvs.
    EXPECT_TRUE(isClosedSurface(*loadGltf(PENUMBRA_SOURCE_DIR "/scenes/assets/duck.glb")));
}

TEST(MeshTopology, TheBuiltInSolidsAreConvexAndOtherSolidsAreNot) {
    EXPECT_TRUE(isConvexSurface(modelOf({makeBox({1, 2, 3})})));
    EXPECT_TRUE(isConvexSurface(modelOf({makeSphere(0.5f, 32)})));
    EXPECT_FALSE(isConvexSurface(modelOf({makePlane({1, 1})})));  // open
    EXPECT_FALSE(isConvexSurface(*loadGltf(PENUMBRA_SOURCE_DIR "/scenes/assets/duck.glb")));
    // Two boxes side by side, each convex: one shadows the other.
    Mesh left = makeBox({1, 1, 1}), right = left;
    for (glm::vec3& p : right.positions) p.x += 2.0f;
    EXPECT_FALSE(isConvexSurface(modelOf({left, right})));
    // A box whose top face is a fan of four triangles round its centre: convex while the centre
    // lies in the face, a pit (closed, not convex) once it is pushed down.
    const auto fanned = [](float centre_y) {
        Mesh box = makeBox({1, 1, 1}), out;
        for (std::size_t t = 0; t + 5 < box.indices.size(); t += 6) {
            const std::uint32_t* q = &box.indices[t];  // a face: (0, 1, 2), (0, 2, 3)
            const glm::vec3 corners[4] = {box.positions[q[0]], box.positions[q[1]],
                                          box.positions[q[2]], box.positions[q[5]]};
            const bool top = corners[0].y > 0.4f && corners[2].y > 0.4f;
            for (int i = 0; i < (top ? 4 : 2); ++i) {
                const glm::vec3 tri[3] = {top ? glm::vec3(0.0f, centre_y, 0.0f) : corners[0],
                                          top ? corners[i] : corners[i + 1],
                                          top ? corners[(i + 1) % 4] : corners[i + 2]};
                for (const glm::vec3& p : tri) {
                    out.indices.push_back(static_cast<std::uint32_t>(out.positions.size()));
                    out.positions.push_back(p);
                }
            }
        }
        return out;
    };
    EXPECT_TRUE(isClosedSurface(modelOf({fanned(0.5f)})));
    EXPECT_TRUE(isConvexSurface(modelOf({fanned(0.5f)})));
    EXPECT_TRUE(isClosedSurface(modelOf({fanned(0.25f)})));
    EXPECT_FALSE(isConvexSurface(modelOf({fanned(0.25f)})));
}

}  // namespace
}  // namespace penumbra::scene
