// Every glTF under /usr/share/assimp/models/glTF2 (many broken on purpose) loads or is refused
// with an InputError, never another exception; and glTF files used through scene files.
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

#include "renderer/scene/gltf_loader.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

TEST(GltfCorpus, EveryAssimpFileLoadsOrIsRefused) {
    const auto dir = test::assimpGltfDir();
    if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " not installed (assimp-testmodels)";
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(dir)) {
        const std::string ext = entry.path().extension().string();
        if (entry.is_regular_file() && (ext == ".gltf" || ext == ".glb"))
            files.push_back(entry.path());
    }
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 40u);
    int loaded = 0;
    for (const auto& file : files) {
        const std::string name = file.lexically_relative(dir).string();
        try {
            const auto model = loadGltf(file);
            std::size_t triangles = 0;
            for (const Mesh& mesh : model->meshes) {
                triangles += mesh.indices.size() / 3;
                ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << name;
                ASSERT_TRUE(mesh.uvs.empty() || mesh.uvs.size() == mesh.positions.size()) << name;
                ASSERT_LT(static_cast<std::size_t>(mesh.material), model->materials.size()) << name;
                for (std::uint32_t i : mesh.indices) ASSERT_LT(i, mesh.positions.size()) << name;
            }
            EXPECT_GT(triangles, 0u) << name;
            std::cout << "loaded   " << name << ": " << model->meshes.size() << " meshes, "
                      << triangles << " triangles, " << model->textures.size() << " textures\n";
            ++loaded;
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u)
                << "does not start with the path: " << message;
            EXPECT_EQ(message.find('\n'), std::string::npos) << message;
            std::cout << "rejected " << name << ": " << message.substr(file.string().size() + 2)
                      << "\n";
        } catch (const std::exception& e) {
            ADD_FAILURE() << name << ": not an InputError: " << e.what();
        }
    }
    std::cout << loaded << " of " << files.size() << " files loaded\n";
    EXPECT_GE(loaded, 20);
}

TEST(GltfCorpus, SceneFileWithAnAssimpModel) {
    const auto box = test::assimpGltfDir() / "BoxTextured-glTF-Binary/BoxTextured.glb";
    if (!std::filesystem::exists(box)) GTEST_SKIP() << box << " not installed";
    nlohmann::json doc = test::minimalScene();
    doc["objects"].push_back({{"name", "crate"},
                              {"gltf", box.string()},
                              {"transform", {{"translate", {1, 0.5, 0}}, {"scale", 0.5}}},
                              {"shadow", "occluder"}});
    const Scene scene = test::loadDoc(doc).at(0);
    const Object& crate = scene.objects.at(2);
    EXPECT_EQ(crate.name, "crate");
    EXPECT_EQ(crate.shadow, ShadowRole::Occluder);
    EXPECT_EQ(crate.model->meshes.size(), 1u);
    EXPECT_EQ(crate.model->textures.size(), 1u);
    EXPECT_EQ(crate.transform[3], glm::vec4(1, 0.5f, 0, 1));

    // A broken model through a scene names the object, then the glTF file and key.
    doc["objects"][2]["gltf"] =
        (test::assimpGltfDir() / "IndexOutOfRange/IndexOutOfRange.gltf").string();
    test::expectMessage(
        test::inputErrorOf([&] { test::loadDoc(doc); }),
        "scene.json: objects.2.gltf: " + doc["objects"][2]["gltf"].get<std::string>() +
            ": meshes.0.primitives.0.indices: index ");
}

TEST(GltfCorpus, RelativePathsAreSharedAndTinted) {
    // with_gltf.json names nodes.gltf as "nodes.gltf" and "./nodes.gltf", and once tinted.
    const SceneSource source = SceneSource::load(test::dataDir() / "with_gltf.json", {});
    const Scene scene = source.at(0);
    ASSERT_EQ(scene.objects.size(), 3u);
    EXPECT_EQ(scene.objects[0].model, scene.objects[1].model);  // loaded once
    EXPECT_NE(scene.objects[0].model, scene.objects[2].model);
    EXPECT_EQ(scene.objects[0].model->materials.at(0).base_color, glm::vec4(0.5f, 0.5f, 1, 1));
    EXPECT_EQ(scene.objects[2].model->materials.at(0).base_color, glm::vec4(0.25f, 0.5f, 1, 1));
    EXPECT_EQ(scene.objects[2].model->meshes.size(), scene.objects[0].model->meshes.size());
    EXPECT_EQ(scene.name, "with_gltf");
}

}  // namespace
}  // namespace penumbra::scene
