// The scene document's objects: one shape each (glTF or primitive), its transform, material
// and shadow role. Models come from the AssetStore so equal shapes share one Model.
#include <cstdio>
#include <functional>

#include "renderer/core/error.h"
#include "renderer/scene/primitives.h"
#include "renderer/scene/scene_json.h"
#include "renderer/scene/transform.h"

namespace penumbra::scene {
namespace {

// Exact text of floats for cache keys ("%a": hexadecimal, no rounding).
std::string exactKey(std::initializer_list<float> values) {
    std::string key;
    char buffer[32];
    for (float v : values) {
        std::snprintf(buffer, sizeof buffer, "%a,", static_cast<double>(v));
        key += buffer;
    }
    return key;
}

float positive(const Field& f, float fallback) {
    const float v = static_cast<float>(f.numberOr(fallback));
    if (!(v > 0.0f)) f.expected("a number > 0");
    return v;
}

glm::vec4 readBaseColor(const Field& material) {
    if (!material.present()) return glm::vec4(1.0f);
    material.expectObject({"base_color"});
    const Field f = material.member("base_color");
    if (!f.present()) return glm::vec4(1.0f);
    const std::size_t n = f.json().is_array() ? f.json().size() : 0;
    if (n != 3 && n != 4) f.expected("3 or 4 numbers in [0, 1]");
    const std::vector<double> v = f.numbers(n);
    for (double c : v)
        if (c < 0.0 || c > 1.0) f.expected("3 or 4 numbers in [0, 1]");
    return {v[0], v[1], v[2], n == 4 ? v[3] : 1.0};
}

// A primitive's Model, one per shape, size and colour (equal objects share it).
std::shared_ptr<const Model> sharedPrimitive(const SceneContext& context, const std::string& shape,
                                             const std::string& size, const glm::vec4& color,
                                             const std::function<Mesh()>& build) {
    const std::string key =
        shape + "|" + size + "|" + exactKey({color.r, color.g, color.b, color.a});
    return context.assets->derived(key, [&] {
        auto model = std::make_shared<Model>();
        model->meshes.push_back(build());
        model->materials.push_back(Material{color, -1});
        model->source = shape;
        return std::shared_ptr<const Model>(model);
    });
}

std::shared_ptr<const Model> readPrimitive(const Field& f, const std::string& shape,
                                           const glm::vec4& color, const SceneContext& context) {
    if (shape == "plane") {
        f.expectObject({"size"});
        const Field size = f.member("size");
        const glm::vec2 s = size.present() ? size.vec2() : glm::vec2(1.0f);
        if (!(s.x > 0.0f && s.y > 0.0f)) size.expected("two numbers > 0");
        return sharedPrimitive(context, shape, exactKey({s.x, s.y}), color,
                               [&] { return makePlane(s); });
    }
    if (shape == "box") {
        f.expectObject({"size"});
        const Field size = f.member("size");
        const glm::vec3 s = size.vec3Or(glm::vec3(1.0f));
        if (!(s.x > 0.0f && s.y > 0.0f && s.z > 0.0f)) size.expected("three numbers > 0");
        return sharedPrimitive(context, shape, exactKey({s.x, s.y, s.z}), color,
                               [&] { return makeBox(s); });
    }
    f.expectObject({"radius", "segments"});
    const float radius = positive(f.member("radius"), 0.5f);
    const Field seg = f.member("segments");
    const int segments = seg.present()
                             ? static_cast<int>(seg.integer(kMinSphereSegments, kMaxSphereSegments))
                             : kDefaultSphereSegments;
    return sharedPrimitive(context, shape, exactKey({radius}) + std::to_string(segments), color,
                           [&] { return makeSphere(radius, segments); });
}

// The glTF's Model, loaded once per file; with a base colour, a tinted copy made once per colour.
std::shared_ptr<const Model> readGltf(const Field& f, const glm::vec4& color,
                                      const SceneContext& context) {
    const std::shared_ptr<const GltfFile> file = readGltfReference(f, context);
    const std::shared_ptr<const Model> model = file->model;
    const std::filesystem::path resolved = resolveAsset(context, f.string());
    if (color == glm::vec4(1.0f)) return model;
    const std::string key = "gltf|" + AssetStore::pathKey(resolved) + "|" +
                            exactKey({color.r, color.g, color.b, color.a});
    return context.assets->derived(key, [&] {
        auto tinted = std::make_shared<Model>(*model);
        for (Material& m : tinted->materials) m.base_color *= color;
        return std::shared_ptr<const Model>(tinted);
    });
}

std::shared_ptr<const Model> readShape(const Field& object, const glm::vec4& color,
                                       const SceneContext& context) {
    std::vector<std::string> present;
    for (const char* s : {"gltf", "plane", "box", "sphere"})
        if (object.member(s).present()) present.emplace_back(s);
    if (present.empty()) object.fail("needs one shape: gltf, plane, box or sphere");
    if (present.size() > 1)
        object.fail("has both '" + present[0] + "' and '" + present[1] +
                    "' (one shape per object)");
    const Field f = object.member(present[0]);
    return present[0] == "gltf" ? readGltf(f, color, context)
                                : readPrimitive(f, present[0], color, context);
}

glm::mat4 readTransform(const Field& object) {
    const Field transform = object.member("transform");
    const Field matrix = object.member("matrix");
    if (transform.present() && matrix.present())
        object.fail("has both 'transform' and 'matrix' (give one)");
    if (matrix.present()) {
        const std::vector<double> v = matrix.numbers(16);
        glm::mat4 m;
        for (int i = 0; i < 16; ++i)
            m[i / 4][i % 4] = static_cast<float>(v[static_cast<std::size_t>(i)]);
        if (const std::string problem = matrixProblem(m); !problem.empty()) matrix.fail(problem);
        return m;
    }
    if (!transform.present()) return glm::mat4(1.0f);
    transform.expectObject({"translate", "rotate", "scale"});
    const glm::vec3 translate = transform.member("translate").vec3Or(glm::vec3(0.0f));
    const glm::vec3 rotate = transform.member("rotate").vec3Or(glm::vec3(0.0f));
    glm::vec3 scale(1.0f);
    if (const Field s = transform.member("scale"); s.present()) {
        if (s.json().is_number()) {
            scale = glm::vec3(static_cast<float>(s.number()));
        } else if (s.json().is_array() && s.json().size() == 3 && s.isNumberArray()) {
            scale = s.vec3();
        } else {
            s.expected("a number or 3 numbers");
        }
        if (scale.x == 0.0f || scale.y == 0.0f || scale.z == 0.0f)
            s.expected("nonzero scale factors");
    }
    const glm::mat4 m = composeTransform(translate, rotate, scale);
    if (const std::string problem = matrixProblem(m); !problem.empty()) transform.fail(problem);
    return m;
}

ShadowRole readShadow(const Field& f) {
    if (!f.present()) return ShadowRole::Both;
    const std::string s = f.string();
    if (s == "both") return ShadowRole::Both;
    if (s == "occluder") return ShadowRole::Occluder;
    if (s == "receiver") return ShadowRole::Receiver;
    if (s == "none") return ShadowRole::None;
    f.fail("unknown shadow role '" + s + "' (allowed: both, occluder, receiver, none)");
}

}  // namespace

std::shared_ptr<const GltfFile> readGltfReference(const Field& f, const SceneContext& context) {
    const std::string path = f.string();
    if (path.empty()) f.fail("empty path");
    try {
        return context.assets->gltfFile(resolveAsset(context, path));
    } catch (const InputError& e) {
        f.fail(e.what());
    }
}

Object buildObject(const Field& o, std::size_t index, const SceneContext& context) {
    o.expectObject(
        {"name", "gltf", "plane", "box", "sphere", "transform", "matrix", "material", "shadow"});
    Object object;
    object.name = "object" + std::to_string(index);
    if (const Field name = o.member("name"); name.present()) object.name = name.string();
    const glm::vec4 color = readBaseColor(o.member("material"));
    object.transform = readTransform(o);
    object.shadow = readShadow(o.member("shadow"));
    object.model = readShape(o, color, context);
    return object;
}

std::vector<Object> buildObjects(const Field& objects, const SceneContext& context) {
    if (!objects.present()) objects.fail("missing (a scene needs at least one object)");
    const std::size_t count = objects.arraySize();
    if (count == 0) objects.fail("empty (a scene needs at least one object)");
    std::vector<Object> out;
    out.reserve(count);
    for (std::size_t i = 0; i < count; ++i)
        out.push_back(buildObject(objects.element(i), i, context));
    return out;
}

}  // namespace penumbra::scene
