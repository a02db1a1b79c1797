// The scene's "camera" block: an explicit camera, or a glTF's camera ({"gltf": ...}) whose
// infinite zfar the objects' bounds replace; every camera checked alike (see scene_json.h).
#include <cmath>

#include "renderer/core/error.h"
#include "renderer/core/json_bounds.h"
#include "renderer/scene/gltf_scene.h"
#include "renderer/scene/scene_json.h"

namespace penumbra::scene {

bool parallelDirections(const glm::vec3& a, const glm::vec3& b) {
    return glm::length(glm::cross(glm::normalize(a), glm::normalize(b))) < 1e-6f;
}

namespace {

// The checks every camera passes, explicit or taken from a glTF.
void checkCamera(const Camera& c, const Field& f) {
    if (!(c.fov_y > 0.0f && c.fov_y < 180.0f)) f.member("fov_y").expected("degrees in (0, 180)");
    if (!(c.near > 0.0f)) f.member("near").expected("a number > 0");
    if (!(c.far > c.near)) f.member("far").fail("must be greater than camera.near");
    const glm::vec3 view = c.target - c.position;
    if (glm::length(view) == 0.0f)
        f.member("target").fail("same as camera.position (no view direction)");
    if (glm::length(c.up) == 0.0f) f.member("up").fail("zero vector");
    if (parallelDirections(view, c.up)) f.member("up").fail("parallel to the view direction");
}

// The placement of the camera a {"gltf": ...} camera names by "index" or "name", else the first.
const GltfPlacement& chosenGltfCamera(const Field& f, const GltfFile& file) {
    const Field index = f.member("index");
    const Field name = f.member("name");
    if (index.present() && name.present()) f.fail("has both 'index' and 'name' (give one)");
    const std::string count = std::to_string(file.cameras.size());
    int wanted = -1;
    if (index.present()) {
        wanted = static_cast<int>(index.integer(0, INT_MAX));
        if (static_cast<std::size_t>(wanted) >= file.cameras.size())
            index.fail("camera " + std::to_string(wanted) + " does not exist (" + file.label +
                       " has " + count + " cameras)");
    } else if (name.present()) {
        const std::string wanted_name = name.string();
        for (std::size_t i = 0; i < file.cameras.size() && wanted < 0; ++i)
            if (file.cameras[i].name == wanted_name) wanted = static_cast<int>(i);
        if (wanted < 0)
            name.fail("no camera named '" + quoteText(wanted_name) + "' in " + file.label);
    }
    if (wanted < 0) {
        if (const GltfPlacement* first = firstPlacedCamera(file)) return *first;
        f.member("gltf").fail(file.label + " has no camera placed in its glTF scene");
    }
    for (const GltfPlacement& p : file.placed_cameras)
        if (p.index == wanted) return p;
    (index.present() ? index : name)
        .fail("camera " + std::to_string(wanted) + " of " + file.label +
              " is placed by no node of its glTF scene");
}

// {"gltf": FILE, "index" or "name"}: that glTF camera; FAR_AUTO when its zfar is infinite.
Camera readGltfCamera(const Field& f, const SceneContext& context, bool& far_auto) {
    f.expectObject({"gltf", "index", "name"});
    const Field path = f.member("gltf");
    const auto file = readGltfReference(path, context);
    const GltfPlacement& placed = chosenGltfCamera(f, *file);
    Camera c;
    try {
        c = cameraFromGltf(*file, placed, checkedBounds(*file));
    } catch (const InputError& e) {
        path.fail(e.what());
    }
    far_auto = !file->cameras[static_cast<std::size_t>(placed.index)].zfar;
    return c;
}

}  // namespace

Camera readCamera(const Field& f, const SceneContext& context, bool& far_auto) {
    Camera c;
    far_auto = false;
    if (!f.present()) return c;
    if (f.json().is_object() && f.json().contains("gltf")) {
        c = readGltfCamera(f, context, far_auto);
        checkCamera(c, f);
        return c;
    }
    f.expectObject({"position", "target", "up", "fov_y", "near", "far"});
    c.position = f.member("position").vec3Or(c.position);
    c.target = f.member("target").vec3Or(c.target);
    c.up = f.member("up").vec3Or(c.up);
    c.fov_y = static_cast<float>(f.member("fov_y").numberOr(c.fov_y));
    c.near = static_cast<float>(f.member("near").numberOr(c.near));
    c.far = static_cast<float>(f.member("far").numberOr(c.far));
    checkCamera(c, f);
    return c;
}

// The world bounds of OBJECTS' vertices (for a glTF camera with an infinite zfar).
Bounds objectBounds(const std::vector<Object>& objects) {
    Bounds b{glm::vec3(INFINITY), glm::vec3(-INFINITY)};
    for (const Object& o : objects)
        for (const Mesh& mesh : o.model->meshes)
            for (const glm::vec3& p : mesh.positions) {
                const glm::vec3 w(o.transform * glm::vec4(p, 1.0f));
                b.min = glm::min(b.min, w);
                b.max = glm::max(b.max, w);
            }
    return b;
}

}  // namespace penumbra::scene
