// The scene document of one glTF file (what `penumbra scene` writes and `render model.glb`
// renders): explicit camera, image, lights and objects, every number a float's exact value so
// that loading the document gives back the same floats.
#include "renderer/scene/gltf_scene.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>

#include "renderer/scene/scene_json.h"

namespace penumbra::scene {
namespace {

using ordered_json = nlohmann::ordered_json;  // keys in the order a person reads them

// The shortest decimal that reads back as F (0.8f as 0.8, not 0.800000011920929).
double shortest(float f) {
    char text[32];
    for (int digits = 1; digits < 9; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, static_cast<double>(f));
        const double d = std::strtod(text, nullptr);
        if (static_cast<float>(d) == f) return d;  // as the loader reads it: double, then float
    }
    return static_cast<double>(f);
}

ordered_json vec(const glm::vec2& v) {
    return {shortest(v.x), shortest(v.y)};
}
ordered_json vec(const glm::vec3& v) {
    return {shortest(v.x), shortest(v.y), shortest(v.z)};
}

ordered_json cameraJson(const Camera& c) {
    return {{"position", vec(c.position)}, {"target", vec(c.target)},  {"up", vec(c.up)},
            {"fov_y", shortest(c.fov_y)},  {"near", shortest(c.near)}, {"far", shortest(c.far)}};
}

ordered_json lightJson(const RectLight& l) {
    return {{"type", "rect"},
            {"position", vec(l.position)},
            {"target", vec(l.target)},
            {"up", vec(l.up)},
            {"size", vec(l.size)},
            {"color", vec(l.color)},
            {"intensity", shortest(l.intensity)}};
}

// The floor under MODEL: a square kFloorSide x the bounding radius, its top at the lowest point.
ordered_json floorJson(const Bounds& model) {
    const float side = kFloorSide * model.radius();
    const glm::vec3 center(model.center().x, model.min.y, model.center().z);
    const double albedo = shortest(kFloorAlbedo);
    return {{"name", "floor"},
            {"plane", {{"size", vec(glm::vec2(side))}}},
            {"transform", {{"translate", vec(center)}}},
            {"material", {{"base_color", {albedo, albedo, albedo}}}},
            {"shadow", "receiver"}};
}

// MODEL's bounds with the floor's square added when there is one.
Bounds withFloor(const Bounds& model, bool floor) {
    if (!floor) return model;
    const float half = 0.5f * kFloorSide * model.radius();
    Bounds b = model;
    b.min = glm::min(b.min, model.center() - glm::vec3(half, 0.0f, half));
    b.max = glm::max(b.max, model.center() + glm::vec3(half, 0.0f, half));
    b.min.y = model.min.y;
    return b;
}

}  // namespace

nlohmann::ordered_json gltfSceneDocument(const GltfFile& file, const std::string& gltf_path,
                                         const std::string& name, const GltfSceneOptions& options,
                                         const ImageSettings& image) {
    const Bounds model = checkedBounds(file);
    const Bounds cover = withFloor(model, options.floor);
    const float aspect = static_cast<float>(image.width) / static_cast<float>(image.height);
    const GltfPlacement* placed = firstPlacedCamera(file);
    const Camera camera =
        placed ? cameraFromGltf(file, *placed, cover) : framingCamera(model, aspect, cover);
    std::vector<RectLight> lights = lightsFromGltf(file, options.light_size);
    if (lights.empty()) lights.push_back(defaultLight(model, options.light_size));

    ordered_json doc = {{"format", kSceneFormat},
                        {"name", name},
                        {"camera", cameraJson(camera)},
                        {"image", {{"width", image.width}, {"height", image.height}}},
                        {"lights", ordered_json::array()},
                        {"objects", ordered_json::array({{{"name", name}, {"gltf", gltf_path}}})}};
    for (const RectLight& light : lights) doc["lights"].push_back(lightJson(light));
    if (options.floor) doc["objects"].push_back(floorJson(model));
    return doc;
}

bool isGltfPath(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".gltf" || ext == ".glb";
}

nlohmann::ordered_json gltfSceneFor(const std::filesystem::path& gltf,
                                    const std::filesystem::path& scene_file,
                                    const GltfSceneOptions& options, const ImageSettings& image,
                                    AssetStore& assets) {
    const auto file = assets.gltfFile(gltf);
    std::filesystem::path folder = scene_file.parent_path();
    std::string reference = gltf.filename().string();
    if (scene_file != gltf) {
        std::error_code ec;
        const std::filesystem::path relative =
            std::filesystem::relative(gltf, folder.empty() ? "." : folder, ec);
        reference =
            (ec || relative.empty() ? std::filesystem::absolute(gltf) : relative).generic_string();
    }
    ordered_json doc = gltfSceneDocument(*file, reference, gltf.stem().string(), options, image);
    const SceneContext context{scene_file.string(), folder, scene_file.stem().string(),
                               kMaxImageSize, &assets};
    (void)buildScene(nlohmann::json::parse(doc.dump()), context);  // it loads: values checked
    return doc;
}

}  // namespace penumbra::scene
