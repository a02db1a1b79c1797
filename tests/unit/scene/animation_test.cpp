// Animation tracks: linear interpolation, holding outside the keys, shape checks, values that
// go out of range refused at load, and at(frame) using the assets loaded once.
#include <gtest/gtest.h>

#include "renderer/scene/animation.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;
using test::expectMessage;
using test::inputErrorOf;

json animated(const json& tracks, const char* frames = "1-11") {
    json doc = test::minimalScene();
    doc["animation"] = {{"frames", frames}, {"tracks", tracks}};
    return doc;
}

TEST(Animation, InterpolatesLinearlyAndHoldsOutside) {
    const SceneSource source = test::loadDoc(animated(json::parse(R"([
        {"key": "lights.0.position", "keys": [[1, [-2, 3, 0]], [11, [2, 3, 0]]]},
        {"key": "camera.fov_y", "keys": [[1, 30], [5, 50], [11, 20]]}])")));
    EXPECT_EQ(source.animationFrames(), std::optional<std::string>("1-11"));
    EXPECT_EQ(source.at(1).lights[0].position, glm::vec3(-2, 3, 0));
    EXPECT_EQ(source.at(6).lights[0].position, glm::vec3(0, 3, 0));
    EXPECT_NEAR(source.at(2).lights[0].position.x, -1.6f, 1e-6f);
    EXPECT_EQ(source.at(11).lights[0].position, glm::vec3(2, 3, 0));
    EXPECT_EQ(source.at(-5).lights[0].position, glm::vec3(-2, 3, 0));  // held before the first key
    EXPECT_EQ(source.at(100).lights[0].position, glm::vec3(2, 3, 0));  // and after the last
    EXPECT_EQ(source.at(3).camera.fov_y, 40.0f);
    EXPECT_EQ(source.at(5).camera.fov_y, 50.0f);
    EXPECT_EQ(source.at(8).camera.fov_y, 35.0f);
    EXPECT_EQ(source.at(8).frame, 8);
    // The document stays the one before animation.
    EXPECT_EQ(source.document()["lights"][0]["position"], json({0, 3, 0}));
}

TEST(Animation, SingleKeyHoldsEverywhere) {
    const SceneSource source = test::loadDoc(
        animated(json::parse(R"([{"key": "lights.0.intensity", "keys": [[4, 2.5]]}])")));
    EXPECT_EQ(source.at(0).lights[0].intensity, 2.5f);
    EXPECT_EQ(source.at(99).lights[0].intensity, 2.5f);
}

TEST(Animation, TrackValueAtIsExactAtKeys) {
    AnimationTrack track;
    track.frames = {0, 3};
    track.values = {json(1), json(2)};
    EXPECT_EQ(trackValueAt(track, 0), json(1));
    EXPECT_TRUE(trackValueAt(track, 0).is_number_integer());  // the key's own value
    EXPECT_DOUBLE_EQ(trackValueAt(track, 1).get<double>(), 1.0 + 1.0 / 3.0);
}

TEST(Animation, AnimatedShapesGetTheirOwnModels) {
    const SceneSource source = test::loadDoc(animated(
        json::parse(R"([{"key": "objects.1.sphere.radius", "keys": [[1, 0.2], [11, 0.4]]}])")));
    const Scene a = source.at(1);
    const Scene b = source.at(1);
    const Scene c = source.at(11);
    EXPECT_EQ(a.objects[1].model, b.objects[1].model);
    EXPECT_NE(a.objects[1].model, c.objects[1].model);
    EXPECT_EQ(a.objects[0].model, c.objects[0].model);  // the floor does not move
    EXPECT_NEAR(glm::length(c.objects[1].model->meshes[0].positions[0]), 0.4f, 1e-6f);
}

TEST(Animation, RejectionsNameTheTrack) {
    const std::string path = (test::scratchDir() / "scene.json").string() + ": ";
    struct Case {
        const char* tracks;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {R"({"key": "lights.0.position"})", "animation.tracks: expected an array"},
        {R"([{"key": "lights.0.position"}])", "animation.tracks.0.keys: missing"},
        {R"([{"keys": [[1, 1]]}])", "animation.tracks.0.key: missing"},
        {R"([{"key": "lights.0.position", "keys": []}])",
         "animation.tracks.0.keys: needs at least one"},
        {R"([{"key": "lights.0.position", "keys": [[1, [0, 1, 0]], [2, [0, 1]]]}])",
         "animation.tracks.0.keys.1.1: expected 3 numbers like lights.0.position, got [0,1]"},
        {R"([{"key": "lights.0.position", "keys": [[1, 5]]}])",
         "animation.tracks.0.keys.0.1: expected 3 numbers like lights.0.position, got 5"},
        {R"([{"key": "camera.fov_y", "keys": [[1, [5]]]}])",
         "animation.tracks.0.keys.0.1: expected a number like camera.fov_y, got [5]"},
        {R"([{"key": "camera.fov_y", "keys": [[1, "wide"]]}])",
         "animation.tracks.0.keys.0.1: expected a number like camera.fov_y, got \"wide\""},
        {R"([{"key": "camera.fov_y", "keys": [[5, 30], [5, 40]]}])",
         "animation.tracks.0.keys.1.0: frame 5 is not after the previous key's frame 5"},
        {R"([{"key": "camera.fov_y", "keys": [[5.5, 30]]}])",
         "animation.tracks.0.keys.0.0: expected an integer"},
        {R"([{"key": "camera.fov_y", "keys": [[1, 30, 2]]}])",
         "animation.tracks.0.keys.0: expected [frame, value], got [1,30,2]"},
        {R"([{"key": "lights.2.position", "keys": [[1, [0, 1, 0]]]}])",
         "animation.tracks.0.key: 'lights.2.position' does not exist in the scene"},
        {R"([{"key": "camera.aperture", "keys": [[1, 2]]}])",
         "animation.tracks.0.key: 'camera.aperture' does not exist in the scene"},
        {R"([{"key": "objects.0.shadow", "keys": [[1, 2]]}])",
         "animation.tracks.0.key: 'objects.0.shadow' is a string, not a number or an array of "
         "numbers"},
        {R"([{"key": "camera", "keys": [[1, 2]]}])",
         "animation.tracks.0.key: 'camera' is an object, not a number or an array of numbers"},
        {R"([{"key": "animation.frames", "keys": [[1, 2]]}])",
         "animation.tracks.0.key: the animation block cannot be animated"},
        {R"([{"key": "camera..fov_y", "keys": [[1, 2]]}])",
         "animation.tracks.0.key: malformed key"},
        {R"([{"key": "camera.fov_y", "keys": [[1, 30]], "ease": "in"}])",
         "animation.tracks.0: unknown key 'ease' (allowed: key, keys)"},
        // A value out of range at a key frame fails at load, naming the track and the key.
        {R"([{"key": "camera.fov_y", "keys": [[1, 30]]}, {"key": "lights.0.intensity", "keys": [[1, 1], [10, -1]]}])",
         "animation.tracks.1.keys.1: at frame 10: lights.0.intensity: expected a number >= 0"},
        {R"([{"key": "objects.1.sphere.radius", "keys": [[0, 1], [4, 0]]}])",
         "animation.tracks.0.keys.1: at frame 4: objects.1.sphere.radius: expected a number > 0"},
        // The image's size and samples are one per render: animating them is refused.
        {R"([{"key": "image.width", "keys": [[0, 64], [10, 65]]}])",
         "animation.tracks.0.key: 'image.width' cannot be animated (one image size per render)"},
        // One track per value.
        {R"([{"key": "camera.fov_y", "keys": [[1, 30]]}, {"key": "camera.fov_y", "keys": [[1, 31]]}])",
         "animation.tracks.1.key: 'camera.fov_y' is animated by animation.tracks.0 already"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.tracks);
        const json doc = animated(json::parse(c.tracks));
        expectMessage(inputErrorOf([&] { test::loadDoc(doc); }), path + c.expected);
    }
}

TEST(Animation, OverridesComeFirst) {
    // The track's key must exist after -D; -D can also create what a track animates.
    const json doc =
        animated(json::parse(R"([{"key": "technique.epsilon", "keys": [[1, 0.1], [11, 0.2]]}])"));
    expectMessage(inputErrorOf([&] { test::loadDoc(doc); }),
                  "'technique.epsilon' does not exist in the scene");
    const SceneSource source =
        test::loadDoc(doc, {{"technique.name", "adaptive"}, {"technique.epsilon", "0.5"}});
    EXPECT_DOUBLE_EQ(source.at(6).technique["epsilon"].get<double>(), 0.15);
}

TEST(Animation, FramesDoNotReloadAssets) {
    // Copy the glTF fixture, load a scene that uses it, delete it: frames still build.
    const auto gltf = test::scratchDir() / "anim-assets" / "nodes.gltf";
    std::filesystem::create_directories(gltf.parent_path());
    std::filesystem::copy_file(test::dataDir() / "nodes.gltf", gltf,
                               std::filesystem::copy_options::overwrite_existing);
    json doc = animated(json::parse(
        R"([{"key": "objects.2.transform.translate", "keys": [[1, [0, 0, 0]], [11, [1, 0, 0]]]}])"));
    doc["objects"].push_back({{"gltf", "nodes.gltf"}, {"transform", {{"translate", {0, 0, 0}}}}});
    const SceneSource source = test::loadDoc(doc, {}, {}, "anim-assets/scene.json");
    const auto model = source.at(1).objects[2].model;
    std::filesystem::remove(gltf);
    const Scene later = source.at(6);
    EXPECT_EQ(later.objects[2].model, model);
    EXPECT_NEAR(later.objects[2].transform[3].x, 0.5f, 1e-6f);
}

}  // namespace
}  // namespace penumbra::scene
