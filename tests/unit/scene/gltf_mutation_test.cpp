// Robustness: glTF files changed at random (JSON values replaced, binary bytes flipped) must load
// or be refused with an InputError, never crash. Deterministic; PENUMBRA_MUTATIONS=N runs more.
#include <gtest/gtest.h>

#include <cstdlib>
#include <random>

#include "gltf_builder.h"
#include "renderer/scene/gltf_loader.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;
using test::GltfBuilder;

int mutationCount(int fallback) {
    const char* env = std::getenv("PENUMBRA_MUTATIONS");
    return env ? std::atoi(env) : fallback;
}

// Every value in DOC, depth first, so one can be picked at random.
void collect(json& doc, std::vector<json*>& out) {
    out.push_back(&doc);
    if (doc.is_object() || doc.is_array())
        for (auto& child : doc) collect(child, out);
}

json randomValue(std::mt19937& rng) {
    static const json kValues[] = {-1,
                                   0,
                                   1,
                                   2,
                                   3,
                                   4,
                                   5,
                                   6,
                                   7,
                                   255,
                                   256,
                                   65535,
                                   65536,
                                   2147483647,
                                   4294967296.0,
                                   1e300,
                                   -1e300,
                                   0.5,
                                   "x",
                                   "VEC3",
                                   json::array(),
                                   json::object(),
                                   nullptr,
                                   true,
                                   json::array({0, 1, 2}),
                                   json::array({1, 0, 0, 0})};
    return kValues[std::uniform_int_distribution<std::size_t>(0, std::size(kValues) - 1)(rng)];
}

void mutateJson(json& doc, std::mt19937& rng) {
    std::vector<json*> values;
    collect(doc, values);
    json* target = values[std::uniform_int_distribution<std::size_t>(1, values.size() - 1)(rng)];
    *target = randomValue(rng);
}

// Loads FILE and reports anything but success or an InputError.
void expectLoadsOrRefuses(const std::filesystem::path& file, const std::string& what) {
    try {
        (void)loadGltf(file);
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << what << ": not an InputError: " << e.what();
    }
}

TEST(GltfMutation, ChangedJsonValues) {
    std::mt19937 rng(1234);
    GltfBuilder quad = GltfBuilder::quad();
    quad.doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}}}}};
    quad.doc["meshes"][0]["primitives"][0]["material"] = 0;
    quad.doc["nodes"] = {{{"children", {1}}, {"translation", {0, 1, 0}}},
                         {{"mesh", 0}, {"scale", {1, 2, 1}}}};
    const int count = mutationCount(300);
    for (int i = 0; i < count; ++i) {
        GltfBuilder b = quad;
        for (int m = 0; m < 1 + i % 3; ++m) mutateJson(b.doc, rng);
        const auto path = i % 2 ? b.writeGlb("mutated") : b.writeGltf("mutated");
        expectLoadsOrRefuses(path, "mutation " + std::to_string(i) + ": " + b.doc.dump());
    }
}

TEST(GltfMutation, ChangedCorpusJson) {
    const auto dir = test::assimpGltfDir();
    if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " not installed";
    // Text glTF files whose buffers sit beside them: copied with their folder, JSON changed.
    const char* const files[] = {"BoxTextured-glTF/BoxTextured.gltf", "draco/2CylinderEngine.gltf",
                                 "textureTransform/TextureTransformTest.gltf",
                                 "simple_skin/simple_skin.gltf"};
    std::mt19937 rng(99);
    const int count = mutationCount(60);
    for (const char* file : files) {
        const auto source = dir / file;
        const auto folder = test::scratchDir() / "mutated-corpus" / source.parent_path().filename();
        std::filesystem::create_directories(folder);
        std::filesystem::copy(source.parent_path(), folder,
                              std::filesystem::copy_options::overwrite_existing |
                                  std::filesystem::copy_options::recursive);
        const json original = json::parse(test::readFile(source));
        for (int i = 0; i < count; ++i) {
            json doc = original;
            mutateJson(doc, rng);
            const auto path = folder / "mutated.gltf";
            std::ofstream(path) << doc.dump();
            expectLoadsOrRefuses(path, std::string(file) + " mutation " + std::to_string(i));
        }
    }
}

TEST(GltfMutation, FlippedBinaryBytes) {
    const auto dir = test::assimpGltfDir();
    if (!std::filesystem::exists(dir)) GTEST_SKIP() << dir << " not installed";
    // GLB containers and Draco streams with bytes overwritten.
    struct Target {
        const char* file;     // copied with its folder
        const char* mutated;  // the file in that folder whose bytes change
        const char* load;     // the file loaded
    };
    const Target targets[] = {
        {"BoxTextured-glTF-Binary/BoxTextured.glb", "BoxTextured.glb", "BoxTextured.glb"},
        {"BoxBadNormals-glTF-Binary/BoxBadNormals.glb", "BoxBadNormals.glb", "BoxBadNormals.glb"},
        {"draco/2CylinderEngine.gltf", "2CylinderEngine.bin", "2CylinderEngine.gltf"},
    };
    std::mt19937 rng(7);
    const int count = mutationCount(60);
    for (const Target& t : targets) {
        const auto source = dir / t.file;
        const auto folder = test::scratchDir() / "flipped" / source.parent_path().filename();
        std::filesystem::create_directories(folder);
        std::filesystem::copy(source.parent_path(), folder,
                              std::filesystem::copy_options::overwrite_existing |
                                  std::filesystem::copy_options::recursive);
        const std::string original = test::readFile(folder / t.mutated);
        for (int i = 0; i < count; ++i) {
            std::string bytes = original;
            const int flips = 1 + i % 8;
            for (int f = 0; f < flips; ++f) {
                const std::size_t at =
                    std::uniform_int_distribution<std::size_t>(0, bytes.size() - 1)(rng);
                bytes[at] = static_cast<char>(std::uniform_int_distribution<int>(0, 255)(rng));
            }
            std::ofstream(folder / t.mutated, std::ios::binary) << bytes;
            expectLoadsOrRefuses(folder / t.load,
                                 std::string(t.file) + " flip " + std::to_string(i));
        }
        std::ofstream(folder / t.mutated, std::ios::binary) << original;
    }
}

TEST(SceneMutation, ChangedSceneValues) {
    // The same for scene files: every value of a scene using all features, changed at random.
    json scene = test::minimalScene();
    scene["environment"] = {{"image", (test::dataDir() / "sky.hdr").string()}, {"intensity", 1}};
    scene["objects"].push_back({{"gltf", (test::dataDir() / "nodes.gltf").string()},
                                {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}},
                                {"material", {{"base_color", {1, 0.5, 0.5, 1}}}}});
    scene["objects"].push_back(
        {{"box", {{"size", {1, 1, 1}}}}, {"transform", {{"rotate", {0, 45, 0}}, {"scale", 2}}}});
    scene["technique"] = {{"name", "adaptive"}, {"epsilon", 0.01}};
    scene["animation"] = {
        {"frames", "1-10"},
        {"tracks",
         {{{"key", "lights.0.position"}, {"keys", {{1, {0, 3, 0}}, {10, {1, 3, 0}}}}},
          {{"key", "objects.3.box.size"}, {"keys", {{1, {1, 1, 1}}, {10, {2, 1, 1}}}}}}}};
    (void)test::loadDoc(scene);  // valid as written
    std::mt19937 rng(5);
    const int count = mutationCount(300);
    for (int i = 0; i < count; ++i) {
        json doc = scene;
        for (int m = 0; m < 1 + i % 2; ++m) mutateJson(doc, rng);
        try {
            const SceneSource source = test::loadDoc(doc, {}, {}, "mutated-scene.json");
            for (int frame : {0, 5, 11}) (void)source.at(frame);
        } catch (const InputError& e) {
            EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << e.what();
        } catch (const std::exception& e) {
            ADD_FAILURE() << "mutation " << i << ": not an InputError: " << e.what() << "\n"
                          << doc.dump();
        }
    }
}

}  // namespace
}  // namespace penumbra::scene
