// Scene documents: what a valid file gives (defaults included) and every rejection, each
// checked to name the file and the dotted key at fault on one line.
#include <gtest/gtest.h>

#include "renderer/scene/scene_source.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;
using test::expectMessage;
using test::inputErrorOf;
using test::loadDoc;
using test::minimalScene;

TEST(SceneJson, MinimalSceneLoadsWithItsValues) {
    const SceneSource source = loadDoc(minimalScene(), {}, {}, "minimal.json");
    const Scene scene = source.at(0);
    EXPECT_EQ(scene.name, "minimal");  // the file's stem
    EXPECT_EQ(scene.image.width, 64);
    EXPECT_EQ(scene.image.height, 48);
    EXPECT_EQ(scene.image.samples, 1);
    ASSERT_EQ(scene.lights.size(), 1u);
    EXPECT_EQ(scene.lights[0].intensity, 5.0f);
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].name, "floor");
    EXPECT_EQ(scene.objects[0].shadow, ShadowRole::Receiver);
    EXPECT_EQ(scene.objects[1].shadow, ShadowRole::Both);
    EXPECT_EQ(scene.objects[1].transform[3], glm::vec4(0, 1, 0, 1));
    EXPECT_EQ(scene.objects[0].model->source, "plane");
    EXPECT_EQ(scene.technique, json({{"name", "hard"}}));
    EXPECT_FALSE(scene.environment.has_value());
    EXPECT_FALSE(source.animationFrames().has_value());
}

TEST(SceneJson, DefaultsFillWhatIsLeftOut) {
    json doc = {{"format", "penumbra-scene/1"},
                {"lights", json::array({json::object()})},
                {"objects", json::array({{{"box", json::object()}}})}};
    const Scene scene = loadDoc(doc).at(3);
    EXPECT_EQ(scene.frame, 3);
    const Camera camera;
    EXPECT_EQ(scene.camera.position, camera.position);
    EXPECT_EQ(scene.camera.fov_y, camera.fov_y);
    EXPECT_EQ(scene.image.width, 1024);
    EXPECT_EQ(scene.image.height, 768);
    EXPECT_EQ(scene.lights[0].size, glm::vec2(1, 1));
    EXPECT_EQ(scene.objects[0].name, "object0");
    EXPECT_EQ(scene.objects[0].transform, glm::mat4(1.0f));
    EXPECT_EQ(scene.objects[0].model->materials.at(0).base_color, glm::vec4(1.0f));
}

TEST(SceneJson, KeepsNameTechniqueParametersAndMaterial) {
    json doc = minimalScene();
    doc["name"] = "shot";
    doc["technique"] = {{"name", "adaptive"}, {"epsilon", 0.01}};
    doc["image"]["samples"] = 4;
    doc["objects"][0]["material"] = {{"base_color", {0.5, 0.25, 1.0}}};
    doc["objects"][1]["material"] = {{"base_color", {0.5, 0.25, 1.0, 0.5}}};
    const Scene scene = loadDoc(doc).at(0);
    EXPECT_EQ(scene.name, "shot");
    EXPECT_EQ(scene.technique["epsilon"], 0.01);
    EXPECT_EQ(scene.image.samples, 4);
    EXPECT_EQ(scene.objects[0].model->materials.at(0).base_color,
              glm::vec4(0.5f, 0.25f, 1.0f, 1.0f));
    EXPECT_EQ(scene.objects[1].model->materials.at(0).base_color,
              glm::vec4(0.5f, 0.25f, 1.0f, 0.5f));
}

TEST(SceneJson, EqualPrimitivesShareOneModel) {
    json doc = minimalScene();
    doc["objects"].push_back({{"sphere", {{"radius", 0.3}}}});
    doc["objects"].push_back({{"sphere", {{"radius", 0.4}}}});
    const Scene scene = loadDoc(doc).at(0);
    EXPECT_EQ(scene.objects[1].model, scene.objects[2].model);
    EXPECT_NE(scene.objects[1].model, scene.objects[3].model);
}

// One rejection: a change to the minimal scene and the part of the message it must produce.
struct Rejection {
    const char* name;
    std::function<void(json&)> change;
    std::string expected;  // after "<scene path>: "
};

const std::vector<Rejection>& rejections() {
    static const std::vector<Rejection> cases = {
        {"format missing", [](json& d) { d.erase("format"); }, "format: missing"},
        {"format wrong", [](json& d) { d["format"] = "penumbra-scene/2"; },
         "format: unsupported format"},
        {"format type", [](json& d) { d["format"] = 1; }, "format: expected a string, got 1"},
        {"unknown top key", [](json& d) { d["camra"] = json::object(); },
         "unknown key 'camra' (did you mean 'camera'? allowed: format, name, camera, image, "
         "lights, "
         "environment, objects, technique, animation)"},
        {"name type", [](json& d) { d["name"] = 5; }, "name: expected a string, got 5"},
        {"name empty", [](json& d) { d["name"] = ""; }, "name: empty name"},
        {"camera type", [](json& d) { d["camera"] = json::array(); },
         "camera: expected an object, got []"},
        {"camera unknown key", [](json& d) { d["camera"]["fov"] = 1; },
         "camera: unknown key 'fov'"},
        {"camera position size",
         [](json& d) {
             d["camera"]["position"] = {1, 2};
         },
         "camera.position: expected 3 numbers, got [1,2]"},
        {"camera position element",
         [](json& d) {
             d["camera"]["position"] = {1, "a", 2};
         },
         "camera.position: expected 3 numbers, got [1,\"a\",2]"},
        {"camera position huge",
         [](json& d) {
             d["camera"]["position"] = {1, 1e39, 2};
         },
         "camera.position: expected 3 numbers within +-3.4e38, got [1,1e+39,2]"},
        {"camera fov 0", [](json& d) { d["camera"]["fov_y"] = 0; },
         "camera.fov_y: expected degrees in (0, 180)"},
        {"camera fov 180", [](json& d) { d["camera"]["fov_y"] = 180; },
         "camera.fov_y: expected degrees in (0, 180)"},
        {"camera fov string", [](json& d) { d["camera"]["fov_y"] = "wide"; },
         "camera.fov_y: expected a number, got \"wide\""},
        {"camera fov huge", [](json& d) { d["camera"]["fov_y"] = 1e300; },
         "camera.fov_y: expected a number within +-3.4e38, got 1e+300"},
        {"camera near 0", [](json& d) { d["camera"]["near"] = 0; },
         "camera.near: expected a number > 0"},
        {"camera far", [](json& d) { d["camera"]["far"] = 0.01; },
         "camera.far: must be greater than camera.near"},
        {"camera target", [](json& d) { d["camera"]["target"] = d["camera"]["position"]; },
         "camera.target: same as camera.position"},
        {"camera up zero",
         [](json& d) {
             d["camera"]["up"] = {0, 0, 0};
         },
         "camera.up: zero vector"},
        {"camera up parallel",
         [](json& d) {
             d["camera"]["target"] = {0, 0, 0};
             d["camera"]["position"] = {0, 5, 0};
         },
         "camera.up: parallel to the view direction"},
        {"image width 0", [](json& d) { d["image"]["width"] = 0; },
         "image.width: expected an integer in 1..16384, got 0"},
        {"image width big", [](json& d) { d["image"]["width"] = 20000; },
         "image.width: expected an integer in 1..16384, got 20000"},
        {"image width fraction", [](json& d) { d["image"]["width"] = 64.5; },
         "image.width: expected an integer in 1..16384, got 64.5"},
        {"image height type", [](json& d) { d["image"]["height"] = "48"; },
         "image.height: expected an integer in 1..16384, got \"48\""},
        {"image samples", [](json& d) { d["image"]["samples"] = 3; },
         "image.samples: expected 1, 2, 4 or 8"},
        {"image unknown key", [](json& d) { d["image"]["msaa"] = 4; }, "image: unknown key 'msaa'"},
        {"lights type", [](json& d) { d["lights"] = json::object(); },
         "lights: expected an array, got {}"},
        {"light type", [](json& d) { d["lights"][0]["type"] = "point"; },
         "lights.0.type: unsupported light type 'point' (supported: rect)"},
        {"light unknown key", [](json& d) { d["lights"][0]["radius"] = 1; },
         "lights.0: unknown key 'radius' (allowed: type, position, target, up, size, color, "
         "intensity)"},
        {"light zero size",
         [](json& d) {
             d["lights"][0]["size"] = {0, 1};
         },
         "lights.0.size: expected a width and height > 0"},
        {"light negative size",
         [](json& d) {
             d["lights"][0]["size"] = {1, -1};
         },
         "lights.0.size: expected a width and height > 0"},
        {"light size shape", [](json& d) { d["lights"][0]["size"] = 1; },
         "lights.0.size: expected 2 numbers, got 1"},
        {"light color",
         [](json& d) {
             d["lights"][0]["color"] = {1, -0.5, 1};
         },
         "lights.0.color: expected three numbers >= 0"},
        {"light intensity", [](json& d) { d["lights"][0]["intensity"] = -1; },
         "lights.0.intensity: expected a number >= 0"},
        {"light target", [](json& d) { d["lights"][0]["target"] = d["lights"][0]["position"]; },
         "lights.0.target: same as position"},
        {"light up parallel",
         [](json& d) {
             d["lights"][0]["up"] = {0, -2, 0};
         },
         "lights.0.up: parallel to the direction the light faces"},
        {"light up zero",
         [](json& d) {
             d["lights"][0]["up"] = {0, 0, 0};
         },
         "lights.0.up: zero vector"},
        {"no light", [](json& d) { d["lights"] = json::array(); },
         "lights: the scene has no light and no environment"},
        {"environment type", [](json& d) { d["environment"] = "sky.exr"; },
         "environment: expected an object"},
        {"environment no image", [](json& d) { d["environment"] = json::object(); },
         "environment.image: missing"},
        {"environment png",
         [](json& d) {
             d["environment"] = {{"image", "sky.png"}};
         },
         "environment.image: " + (test::scratchDir() / "sky.png").string() +
             ": expected an .exr or .hdr file"},
        {"environment missing",
         [](json& d) {
             d["environment"] = {{"image", "nowhere/sky.exr"}};
         },
         "environment.image: " + (test::scratchDir() / "nowhere/sky.exr").string() +
             ": no such file"},
        {"environment unknown key",
         [](json& d) {
             d["environment"] = {{"image", "a.exr"}, {"exposure", 1}};
         },
         "environment: unknown key 'exposure' (allowed: image, intensity, rotation_y)"},
        {"objects missing", [](json& d) { d.erase("objects"); }, "objects: missing"},
        {"objects empty", [](json& d) { d["objects"] = json::array(); }, "objects: empty"},
        {"object type", [](json& d) { d["objects"][1] = "ball"; },
         "objects.1: expected an object, got \"ball\""},
        {"object no shape", [](json& d) { d["objects"][1].erase("sphere"); },
         "objects.1: needs one shape: gltf, plane, box or sphere"},
        {"object two shapes", [](json& d) { d["objects"][0]["box"] = json::object(); },
         "objects.0: has both 'plane' and 'box' (one shape per object)"},
        {"object unknown key", [](json& d) { d["objects"][1]["transfrom"] = json::object(); },
         "objects.1: unknown key 'transfrom' (did you mean 'transform'? allowed: name, gltf, "
         "plane, "
         "box, sphere, transform, matrix, material, shadow)"},
        {"object name type", [](json& d) { d["objects"][1]["name"] = 3; },
         "objects.1.name: expected a string, got 3"},
        {"plane size",
         [](json& d) {
             d["objects"][0]["plane"]["size"] = {0, 1};
         },
         "objects.0.plane.size: expected two numbers > 0"},
        {"plane unknown key", [](json& d) { d["objects"][0]["plane"]["width"] = 1; },
         "objects.0.plane: unknown key 'width' (allowed: size)"},
        {"box size shape",
         [](json& d) {
             d["objects"][1] = {{"box", {{"size", {1, 1}}}}};
         },
         "objects.1.box.size: expected 3 numbers, got [1,1]"},
        {"box size negative",
         [](json& d) {
             d["objects"][1] = {{"box", {{"size", {1, -1, 1}}}}};
         },
         "objects.1.box.size: expected three numbers > 0"},
        {"sphere radius", [](json& d) { d["objects"][1]["sphere"]["radius"] = 0; },
         "objects.1.sphere.radius: expected a number > 0"},
        {"sphere segments big", [](json& d) { d["objects"][1]["sphere"]["segments"] = 5000; },
         "objects.1.sphere.segments: expected an integer in 3..1024, got 5000"},
        {"sphere segments small", [](json& d) { d["objects"][1]["sphere"]["segments"] = 2; },
         "objects.1.sphere.segments: expected an integer in 3..1024, got 2"},
        {"shape type", [](json& d) { d["objects"][1]["sphere"] = 0.3; },
         "objects.1.sphere: expected an object, got 0.3"},
        {"gltf type",
         [](json& d) {
             d["objects"][1] = {{"gltf", 7}};
         },
         "objects.1.gltf: expected a string, got 7"},
        {"gltf missing",
         [](json& d) {
             d["objects"][1] = {{"gltf", "missing.glb"}};
         },
         "objects.1.gltf: " + (test::scratchDir() / "missing.glb").string() + ": no such file"},
        {"transform type",
         [](json& d) {
             d["objects"][1]["transform"] = {1, 2, 3};
         },
         "objects.1.transform: expected an object, got [1,2,3]"},
        {"transform unknown key",
         [](json& d) {
             d["objects"][1]["transform"]["rotation"] = {0, 0, 0};
         },
         "objects.1.transform: unknown key 'rotation' (allowed: translate, rotate, scale)"},
        {"transform scale string", [](json& d) { d["objects"][1]["transform"]["scale"] = "big"; },
         "objects.1.transform.scale: expected a number or 3 numbers"},
        {"transform scale 2",
         [](json& d) {
             d["objects"][1]["transform"]["scale"] = {1, 2};
         },
         "objects.1.transform.scale: expected a number or 3 numbers"},
        {"transform scale zero",
         [](json& d) {
             d["objects"][1]["transform"]["scale"] = {1, 0, 1};
         },
         "objects.1.transform.scale: expected nonzero scale factors"},
        {"transform rotate",
         [](json& d) {
             d["objects"][1]["transform"]["rotate"] = {0, "x", 0};
         },
         "objects.1.transform.rotate: expected 3 numbers, got [0,\"x\",0]"},
        {"transform and matrix",
         [](json& d) {
             d["objects"][1]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
         },
         "objects.1: has both 'transform' and 'matrix'"},
        {"matrix size",
         [](json& d) { d["objects"][0]["matrix"] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0}; },
         "objects.0.matrix: expected 16 numbers, got [1,0,0,0,0,1,0,0,0,0,1,0,0,0,0]"},
        {"matrix singular",
         [](json& d) {
             d["objects"][0]["matrix"] = {1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
         },
         "objects.0.matrix: not invertible"},
        {"matrix projective",
         [](json& d) {
             d["objects"][0]["matrix"] = {1, 0, 0, 0.5, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
         },
         "objects.0.matrix: not affine"},
        {"material type", [](json& d) { d["objects"][0]["material"] = "red"; },
         "objects.0.material: expected an object"},
        {"material unknown key",
         [](json& d) {
             d["objects"][0]["material"] = {{"roughness", 0.5}};
         },
         "objects.0.material: unknown key 'roughness' (allowed: base_color)"},
        {"base color range",
         [](json& d) {
             d["objects"][0]["material"] = {{"base_color", {2, 0, 0}}};
         },
         "objects.0.material.base_color: expected 3 or 4 numbers in [0, 1]"},
        {"base color size",
         [](json& d) {
             d["objects"][0]["material"] = {{"base_color", {1, 1}}};
         },
         "objects.0.material.base_color: expected 3 or 4 numbers"},
        {"shadow", [](json& d) { d["objects"][0]["shadow"] = "sometimes"; },
         "objects.0.shadow: unknown shadow role 'sometimes' (allowed: both, occluder, receiver, "
         "none)"},
        {"technique type", [](json& d) { d["technique"] = "hard"; },
         "technique: expected an object, got \"hard\""},
        {"technique no name",
         [](json& d) {
             d["technique"] = {{"epsilon", 1}};
         },
         "technique.name: missing"},
        {"technique name type",
         [](json& d) {
             d["technique"] = {{"name", 1}};
         },
         "technique.name: expected a string, got 1"},
        {"animation type", [](json& d) { d["animation"] = json::array(); },
         "animation: expected an object, got []"},
        {"animation unknown key",
         [](json& d) {
             d["animation"] = {{"fps", 24}};
         },
         "animation: unknown key 'fps' (allowed: frames, tracks)"},
        {"animation frames",
         [](json& d) {
             d["animation"] = {{"frames", "5-1"}};
         },
         "animation.frames: "},
        {"animation frames type",
         [](json& d) {
             d["animation"] = {{"frames", 10}};
         },
         "animation.frames: expected a string, got 10"},
    };
    return cases;
}

TEST(SceneJson, EveryRejectionNamesItsKey) {
    const std::string path = (test::scratchDir() / "rejected.json").string();
    for (const Rejection& c : rejections()) {
        SCOPED_TRACE(c.name);
        json doc = minimalScene();
        c.change(doc);
        const std::string message = inputErrorOf([&] { loadDoc(doc, {}, {}, "rejected.json"); });
        expectMessage(message, path + ": " + c.expected);
    }
}

TEST(SceneJson, MaxImageSizeComesFromTheOptions) {
    LoadOptions options;
    options.max_image_size = 32;
    expectMessage(inputErrorOf([&] { loadDoc(minimalScene(), {}, options); }),
                  "image.width: expected an integer in 1..32, got 64");
}

TEST(SceneJson, FileErrorsNameThePath) {
    const std::string missing = (test::scratchDir() / "no-such-scene.json").string();
    expectMessage(inputErrorOf([&] { SceneSource::load(missing, {}); }),
                  missing + ": no such file");
    const auto dir = test::scratchDir();
    expectMessage(inputErrorOf([&] { SceneSource::load(dir, {}); }),
                  dir.string() + ": is a folder");
}

TEST(SceneJson, MalformedJsonGivesThePosition) {
    const auto path = test::writeFile(
        "broken.json", "{\n  \"format\": \"penumbra-scene/1\",\n  \"camera\": {,}\n}");
    const std::string message = inputErrorOf([&] { SceneSource::load(path, {}); });
    expectMessage(message, path.string() + ": invalid JSON: ");
    expectMessage(message, "line 3, column 14");
    const auto array = test::writeFile("array.json", "[1, 2]");
    expectMessage(inputErrorOf([&] { SceneSource::load(array, {}); }),
                  array.string() + ": expected a JSON object, got [1,2]");
    const auto overflow = test::writeFile("overflow.json", R"({"format": 1e999})");
    expectMessage(inputErrorOf([&] { SceneSource::load(overflow, {}); }),
                  overflow.string() + ": invalid JSON");
}

TEST(SceneJson, DuplicateKeysAreRefused) {
    const auto path = test::writeFile(
        "duplicate.json",
        R"({"format": "penumbra-scene/1", "lights": [{}], "objects": [{"box": {}, "name": "a", "name": "b"}]})");
    expectMessage(inputErrorOf([&] { SceneSource::load(path, {}); }),
                  path.string() + ": objects.0: duplicate key 'name'");
    const auto top = test::writeFile("duplicate-top.json", R"({"format": "a", "format": "b"})");
    expectMessage(inputErrorOf([&] { SceneSource::load(top, {}); }),
                  top.string() + ": duplicate key 'format'");
}

TEST(SceneJson, EnvironmentAloneLightsTheScene) {
    // The environment image itself is covered in environment_image_test.cpp; here only that a
    // scene without lights but with an environment is accepted.
    json doc = minimalScene();
    doc["lights"] = json::array();
    doc["environment"] = {
        {"image", (test::dataDir() / "sky.hdr").string()}, {"intensity", 2}, {"rotation_y", 90}};
    const Scene scene = loadDoc(doc).at(0);
    ASSERT_TRUE(scene.environment.has_value());
    EXPECT_EQ(scene.environment->intensity, 2.0f);
    EXPECT_EQ(scene.environment->rotation_y, 90.0f);
    ASSERT_TRUE(scene.environment->image);
    EXPECT_EQ(scene.environment->image->width, 8);
    EXPECT_EQ(scene.environment->image->height, 4);
}

}  // namespace
}  // namespace penumbra::scene
