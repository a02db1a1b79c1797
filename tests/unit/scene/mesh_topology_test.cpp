// Closed-surface test: the built-in solids close, a plane and a box with a face missing or
// turned do not, and seams that repeat a position still close.
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

}  // namespace
}  // namespace penumbra::scene
