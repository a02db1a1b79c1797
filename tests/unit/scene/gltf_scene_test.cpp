// A scene made from a glTF file (render model.glb, penumbra scene) and a scene's {"gltf": ...}
// camera and lights: camera from a node under a parent, the framing camera, punctual lights,
// the default light, the floor, and the refusals of bad cameras, lights and references.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <glm/gtc/matrix_transform.hpp>

#include "gltf_builder.h"
#include "renderer/scene/gltf_scene.h"
#include "scene_test_support.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;
using test::expectMessage;
using test::expectNear;
using test::GltfBuilder;
using test::inputErrorOf;

glm::vec3 forwardOf(const Camera& c) {
    return glm::normalize(c.target - c.position);
}

// The unit quad (XY plane, 0..1) with node 1, a parent turned 90 degrees about +Y and moved to
// (0, 0, 10), and node 2 under it, moved 1 along +X, placing camera 0.
GltfBuilder quadWithCamera(const json& camera) {
    GltfBuilder b = GltfBuilder::quad();
    const double s = std::sqrt(0.5);
    b.doc["nodes"].push_back(
        {{"translation", {0, 0, 10}}, {"rotation", {0, s, 0, s}}, {"children", {2}}});
    b.doc["nodes"].push_back({{"translation", {1, 0, 0}}, {"camera", 0}});
    b.doc["scenes"][0]["nodes"] = {0, 1};
    b.doc["cameras"] = {camera};
    return b;
}

json perspective(double yfov, double znear, std::optional<double> zfar = std::nullopt) {
    json p = {{"yfov", yfov}, {"znear", znear}};
    if (zfar) p["zfar"] = *zfar;
    return {{"type", "perspective"}, {"perspective", p}};
}

// A light node placing punctual light LIGHT at TRANSLATION (rotation: quaternion).
void addLight(GltfBuilder& b, const json& light, const json& translation,
              const json& rotation = {0, 0, 0, 1}) {
    auto& lights = b.doc["extensions"]["KHR_lights_punctual"]["lights"];
    lights.push_back(light);
    b.doc["nodes"].push_back(
        {{"translation", translation},
         {"rotation", rotation},
         {"extensions", {{"KHR_lights_punctual", {{"light", lights.size() - 1}}}}}});
    b.doc["scenes"][0]["nodes"].push_back(b.doc["nodes"].size() - 1);
}

Scene loadModel(const std::filesystem::path& path, const std::vector<Override>& overrides = {},
                const GltfSceneOptions& gltf = {}) {
    LoadOptions options;
    options.gltf = gltf;
    return SceneSource::load(path, overrides, options).at(0);
}

TEST(GltfScene, CameraFromANodeUnderATurnedParent) {
    const auto path = quadWithCamera(perspective(0.5, 0.1, 100.0)).writeGlb("camera");
    const Scene s = loadModel(path);
    expectNear(s.camera.position, {0, 0, 9});     // (0,0,10) + Ry(90)(1,0,0)
    expectNear(forwardOf(s.camera), {-1, 0, 0});  // Ry(90)(0,0,-1)
    expectNear(s.camera.up, {0, 1, 0});
    EXPECT_NEAR(s.camera.fov_y, 0.5 * 180.0 / std::numbers::pi, 1e-4);
    EXPECT_FLOAT_EQ(s.camera.near, 0.1f);
    EXPECT_FLOAT_EQ(s.camera.far, 100.0f);
    EXPECT_EQ(s.name, "camera");
}

TEST(GltfScene, InfiniteZfarCoversTheModelAndTheFloor) {
    const auto path = quadWithCamera(perspective(0.5, 0.1)).writeGltf("infinite");
    const Scene s = loadModel(path);
    const Bounds quad{{0, 0, 0}, {1, 1, 0}};
    const float half = 0.5f * kFloorSide * quad.radius();
    float farthest = 0.0f;  // the box around the quad and the floor square
    for (float x : {0.5f - half, 0.5f + half})
        for (float y : {0.0f, 1.0f})
            for (float z : {-half, half})
                farthest = std::max(farthest, glm::length(glm::vec3(x, y, z) - s.camera.position));
    EXPECT_GE(s.camera.far, farthest);
    EXPECT_LE(s.camera.far, farthest * kFarMargin * 1.001f);
}

TEST(GltfScene, NamedCameraWithInfiniteZfarCoversTheScenesObjects) {
    quadWithCamera(perspective(0.5, 0.1)).writeGltf("infinite_ref");
    json doc = test::minimalScene();  // a floor 8 x 8 at y = 0
    doc["camera"] = {{"gltf", "infinite_ref.gltf"}};
    const Scene s = test::loadDoc(doc).at(0);
    // The farthest corner of the box around the floor and the ball (radius 0.3 at y = 1).
    const float corner = glm::length(glm::vec3(4, 1.3f, -4) - s.camera.position);
    EXPECT_GE(s.camera.far, corner);
    EXPECT_LE(s.camera.far, corner * kFarMargin * 1.001f);
}

// Every corner of BOX inside the camera's frustum at WIDTH x HEIGHT.
void expectInView(const Camera& c, const Bounds& box, int width, int height) {
    const glm::mat4 view = glm::lookAt(c.position, c.target, c.up);
    const glm::mat4 projection =
        glm::perspective(glm::radians(c.fov_y),
                         static_cast<float>(width) / static_cast<float>(height), c.near, c.far);
    for (int i = 0; i < 8; ++i) {
        const glm::vec3 corner((i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                               (i & 4) ? box.max.z : box.min.z);
        const glm::vec4 clip = projection * view * glm::vec4(corner, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        EXPECT_LT(std::abs(ndc.x), 1.0f) << "corner " << i << " at " << width << "x" << height;
        EXPECT_LT(std::abs(ndc.y), 1.0f) << "corner " << i << " at " << width << "x" << height;
        EXPECT_LT(std::abs(ndc.z), 1.0f) << "corner " << i;
    }
}

TEST(GltfScene, FramingCameraKeepsTheModelInView) {
    GltfBuilder b = GltfBuilder::quad();
    b.doc["nodes"][0]["scale"] = {3, 1, 0.5};  // a wide model: the narrow image's width limits
    const auto path = b.writeGlb("framed");
    const Bounds box{{0, 0, 0}, {3, 1, 0}};
    expectInView(loadModel(path).camera, box, 1024, 768);
    const Scene tall = loadModel(path, {{"lights.0.intensity", "3"},  // not the image's: ignored
                                        {"image.width", "200"},
                                        {"image.height", "800"}});
    expectInView(tall.camera, box, 200, 800);
    // Tight: the bounding sphere touches the narrower field (x kFramingMargin), not far inside.
    const float distance = glm::length(tall.camera.position - box.center());
    const float half_x = std::atan(std::tan(glm::radians(kFramingFovY / 2)) * 0.25f);
    EXPECT_NEAR(distance, box.radius() * kFramingMargin / std::sin(half_x), 1e-3f);
}

TEST(GltfScene, PointSpotAndDirectionalLights) {
    GltfBuilder b = GltfBuilder::quad();
    addLight(b, {{"type", "point"}, {"intensity", 10}, {"color", {1, 0.5, 0.25}}}, {0.5, 3, 0});
    const double s = std::sqrt(0.5);  // -90 degrees about X: -Z turns to -Y (down)
    addLight(b, {{"type", "spot"}, {"intensity", 4}, {"spot", {{"outerConeAngle", 0.5}}}},
             {2, 2, 2}, {-s, 0, 0, s});
    addLight(b, {{"type", "directional"}, {"intensity", 3}}, {100, 100, 100}, {-s, 0, 0, s});
    GltfSceneOptions options;
    options.light_size = glm::vec2(0.5f, 0.25f);
    const Scene scene = loadModel(b.writeGlb("lights"), {}, options);
    ASSERT_EQ(scene.lights.size(), 3u);
    const RectLight& point = scene.lights[0];
    expectNear(point.position, {0.5, 3, 0});
    expectNear(point.forward(), glm::normalize(glm::vec3(0.5, 0.5, 0) - point.position));
    expectNear(point.color, {1, 0.5, 0.25});
    EXPECT_FLOAT_EQ(point.intensity, 10.0f / (0.5f * 0.25f));  // candela / area
    EXPECT_EQ(point.size, glm::vec2(0.5f, 0.25f));
    const RectLight& spot = scene.lights[1];
    expectNear(spot.position, {2, 2, 2});
    expectNear(spot.forward(), {0, -1, 0});
    EXPECT_FLOAT_EQ(spot.intensity, 4.0f / (0.5f * 0.25f));
    const RectLight& sun = scene.lights[2];
    const Bounds quad{{0, 0, 0}, {1, 1, 0}};
    const float distance = kDirectionalDistance * quad.radius();
    expectNear(sun.position, quad.center() + glm::vec3(0, distance, 0));  // not the node's place
    expectNear(sun.forward(), {0, -1, 0});
    EXPECT_NEAR(sun.intensity, 3.0f * distance * distance / (0.5f * 0.25f), 1e-3f);
}

TEST(GltfScene, DefaultLightAboveAndFloorUnderTheModel) {
    GltfBuilder b = GltfBuilder::quad();
    b.doc["nodes"][0]["translation"] = {0, 2, 0};  // lowest point y = 2
    const Scene s = loadModel(b.writeGlb("plain"));
    const Bounds quad{{0, 2, 0}, {1, 3, 0}};
    ASSERT_EQ(s.lights.size(), 1u);
    const RectLight& light = s.lights[0];
    EXPECT_GT(light.position.y, quad.max.y + quad.radius());
    expectNear(light.target, quad.center());
    expectNear(glm::vec3(light.size, 0), glm::vec3(quad.radius(), quad.radius(), 0));
    ASSERT_EQ(s.objects.size(), 2u);
    EXPECT_EQ(s.objects[1].name, "floor");
    EXPECT_EQ(s.objects[1].shadow, ShadowRole::Receiver);
    EXPECT_EQ(s.objects[1].model->source, "plane");
    expectNear(glm::vec3(s.objects[1].transform[3]), {0.5, 2, 0});
    EXPECT_EQ(s.objects[0].shadow, ShadowRole::Both);

    GltfSceneOptions no_floor;
    no_floor.floor = false;
    const Scene bare = loadModel(b.writeGlb("plain"), {}, no_floor);
    ASSERT_EQ(bare.objects.size(), 1u);
    EXPECT_EQ(bare.objects[0].model->source, b.writeGlb("plain").string());
}

TEST(GltfScene, WrittenSceneLoadsToTheSameValues) {
    GltfBuilder b = quadWithCamera(perspective(0.7, 0.05));
    addLight(b, {{"type", "point"}, {"intensity", 7}}, {0.3, 2.7, 1.1});
    const auto glb = b.writeGlb("roundtrip");
    const Scene direct = loadModel(glb);
    AssetStore assets;
    const auto out = test::scratchDir() / "written/sub/roundtrip.json";
    const nlohmann::ordered_json doc = gltfSceneFor(glb, out, {}, ImageSettings{}, assets);
    EXPECT_EQ(doc["objects"][0]["gltf"], "../../roundtrip.glb");
    const Scene written =
        SceneSource::load(test::writeFile("written/sub/roundtrip.json", doc.dump(2)), {}).at(0);
    EXPECT_EQ(written.camera.position, direct.camera.position);
    EXPECT_EQ(written.camera.target, direct.camera.target);
    EXPECT_EQ(written.camera.far, direct.camera.far);
    ASSERT_EQ(written.lights.size(), direct.lights.size());
    EXPECT_EQ(written.lights[0].intensity, direct.lights[0].intensity);
    EXPECT_EQ(written.lights[0].target, direct.lights[0].target);
    EXPECT_EQ(written.name, "roundtrip");
}

TEST(GltfScene, SceneNamesAGltfCameraAndLights) {
    GltfBuilder b = quadWithCamera(perspective(0.5, 0.1, 50.0));
    b.doc["cameras"][0]["name"] = "Side";
    addLight(b, {{"type", "point"}, {"intensity", 2}}, {0, 4, 0});
    addLight(b, {{"type", "point"}, {"intensity", 3}}, {0, 5, 0});
    b.writeGltf("named");
    json doc = test::minimalScene();
    doc["camera"] = {{"gltf", "named.gltf"}, {"name", "Side"}};
    doc["lights"] = {{{"gltf", "named.gltf"}, {"size", {1, 2}}}, doc["lights"][0]};
    const Scene s = test::loadDoc(doc).at(0);
    expectNear(s.camera.position, {0, 0, 9});
    EXPECT_FLOAT_EQ(s.camera.far, 50.0f);
    ASSERT_EQ(s.lights.size(), 3u);
    EXPECT_FLOAT_EQ(s.lights[1].intensity, 1.5f);
    EXPECT_EQ(s.lights[1].size, glm::vec2(1, 2));
    EXPECT_FLOAT_EQ(s.lights[2].intensity, 5.0f);  // the scene's own light, after them
    doc["camera"] = {{"gltf", "named.gltf"}, {"index", 0}};
    EXPECT_EQ(test::loadDoc(doc).at(0).camera.position, s.camera.position);
}

TEST(GltfScene, RefusesBadCamerasAndLights) {
    auto error = [](GltfBuilder b) {
        return inputErrorOf([&] { (void)loadModel(b.writeGlb("bad")); });
    };
    expectMessage(error(quadWithCamera(perspective(3.2, 0.1))),
                  "bad.glb: cameras.0.perspective.yfov: must be in (0, pi) radians");
    expectMessage(error(quadWithCamera(perspective(0.5, 0.0))),
                  "bad.glb: cameras.0.perspective.znear: must be > 0");
    expectMessage(error(quadWithCamera(perspective(0.5, 1.0, 0.5))),
                  "cameras.0.perspective.zfar: must be greater than znear");
    expectMessage(error(quadWithCamera(
                      {{"type", "perspective"}, {"perspective", {{"yfov", "x"}, {"znear", 1}}}})),
                  "cameras.0.perspective.yfov: expected a number, got \"x\"");
    expectMessage(error(quadWithCamera(
                      {{"type", "orthographic"},
                       {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 9}}}})),
                  "bad.glb: cameras.0: an orthographic camera: penumbra renders perspective");
    GltfBuilder missing = quadWithCamera(perspective(0.5, 0.1));
    missing.doc["nodes"][2]["camera"] = 3;
    expectMessage(error(missing), "bad.glb: nodes.2.camera: camera 3 does not exist");
    GltfBuilder flat = quadWithCamera(perspective(0.5, 0.1));
    flat.doc["nodes"][2]["scale"] = {1, 1, 0};
    expectMessage(error(flat), "bad.glb: nodes.2: the camera's transform gives no position");

    GltfBuilder lights = GltfBuilder::quad();
    addLight(lights, {{"type", "point"}, {"intensity", -1}}, {0, 3, 0});
    expectMessage(error(lights), "extensions.KHR_lights_punctual.lights.0.intensity: must be >= 0");
    GltfBuilder spot = GltfBuilder::quad();
    addLight(spot, {{"type", "spot"}}, {0, 3, 0});
    expectMessage(error(spot), "lights.0.spot: missing");
    GltfBuilder area = GltfBuilder::quad();
    addLight(area, {{"type", "area"}}, {0, 3, 0});
    expectMessage(error(area), "lights.0.type: unknown light type 'area'");
    GltfBuilder many = GltfBuilder::quad();
    for (std::size_t i = 0; i <= kMaxGltfLights; ++i)
        addLight(many, {{"type", "point"}}, {0, 3, 0});
    expectMessage(error(many), "places 65 lights, more than 64");
    GltfBuilder dangling = GltfBuilder::quad();
    addLight(dangling, {{"type", "point"}}, {0, 3, 0});
    dangling.doc["nodes"][1]["extensions"]["KHR_lights_punctual"]["light"] = 1;
    expectMessage(error(dangling),
                  "nodes.1.extensions.KHR_lights_punctual.light: light 1 does not exist");
}

TEST(GltfScene, RefusesBadReferences) {
    GltfBuilder b = quadWithCamera(perspective(0.5, 0.1));
    b.writeGltf("ref");
    GltfBuilder::quad().writeGltf("bare");
    auto error = [](const json& camera, const json& lights) {
        json doc = test::minimalScene();
        if (!camera.is_null()) doc["camera"] = camera;
        if (!lights.is_null()) doc["lights"] = lights;
        return inputErrorOf([&] { (void)test::loadDoc(doc); });
    };
    expectMessage(error({{"gltf", "ref.gltf"}, {"index", 1}}, nullptr),
                  "scene.json: camera.index: camera 1 does not exist");
    expectMessage(error({{"gltf", "ref.gltf"}, {"index", -1}}, nullptr), "camera.index:");
    expectMessage(error({{"gltf", "ref.gltf"}, {"name", "Nope"}}, nullptr),
                  "camera.name: no camera named 'Nope'");
    expectMessage(error({{"gltf", "ref.gltf"}, {"index", 0}, {"name", "x"}}, nullptr),
                  "camera: has both 'index' and 'name'");
    expectMessage(error({{"gltf", "ref.gltf"}, {"fov_y", 30}}, nullptr),
                  "camera: unknown key 'fov_y' (allowed: gltf, index, name)");
    expectMessage(error({{"gltf", "bare.gltf"}}, nullptr),
                  "camera.gltf: " + (test::scratchDir() / "bare.gltf").string() +
                      " has no camera placed in its glTF scene");
    expectMessage(error({{"gltf", 3}}, nullptr), "camera.gltf: expected a string");
    expectMessage(error({{"gltf", "gone.glb"}}, nullptr), "camera.gltf: ");
    expectMessage(error(nullptr, json::array({{{"gltf", "ref.gltf"}}})),
                  "lights.0.gltf: " + (test::scratchDir() / "ref.gltf").string() +
                      " has no KHR_lights_punctual light");
    expectMessage(error(nullptr, json::array({{{"gltf", "ref.gltf"}, {"size", {0, 1}}}})),
                  "lights.0.size: expected a width and height > 0");
    expectMessage(error(nullptr, json::array({{{"gltf", "ref.gltf"}, {"sise", {1, 1}}}})),
                  "lights.0: unknown key 'sise' (did you mean 'size'?");
}

}  // namespace
}  // namespace penumbra::scene
