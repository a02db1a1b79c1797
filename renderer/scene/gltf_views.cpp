// A glTF's cameras and KHR_lights_punctual lights, and the nodes that place them, read from the
// document's JSON with every value checked (type, finite, range, references), since tinygltf
// reads a wrongly typed field as absent and keeps NaN-free but absurd values.
#include <climits>
#include <cmath>
#include <numbers>

#include "renderer/core/json_bounds.h"
#include "renderer/core/json_field.h"
#include "renderer/scene/gltf_document.h"

namespace penumbra::scene {
namespace {

using nlohmann::json;

class ViewReader {
public:
    explicit ViewReader(const GltfDocument& doc) : doc_(doc) {}

    [[noreturn]] void fail(const std::string& key, const std::string& what) const {
        doc_.fail(key, what);
    }
    static const json* find(const json& obj, const char* name) {
        const auto it = obj.find(name);
        return it == obj.end() ? nullptr : &*it;
    }
    Field at(const json& v, const std::string& key) const { return Field(&v, key, doc_.label); }
    const json& object(const json& v, const std::string& key) const {
        at(v, key).expectObject();
        return v;
    }
    const json& array(const json& v, const std::string& key) const {
        (void)at(v, key).arraySize();
        return v;
    }
    // A finite number.
    double number(const json& v, const std::string& key) const { return at(v, key).number(); }
    std::string string(const json& v, const std::string& key) const { return at(v, key).string(); }
    // An index into an array of COUNT WHATs.
    int reference(const json& v, const std::string& key, std::size_t count,
                  const char* what) const {
        const long i = at(v, key).strictInteger(0, INT_MAX);
        if (static_cast<std::size_t>(i) >= count)
            fail(key, std::string(what) + " " + std::to_string(i) + " does not exist");
        return static_cast<int>(i);
    }
    std::string optName(const json& obj, const std::string& key) const {
        const json* name = find(obj, "name");
        return name ? string(*name, key + ".name") : std::string();
    }

private:
    const GltfDocument& doc_;
};

GltfCamera readCamera(const ViewReader& r, const json& c, const std::string& key) {
    r.object(c, key);
    GltfCamera camera;
    camera.name = r.optName(c, key);
    const json* type = ViewReader::find(c, "type");
    if (!type) r.fail(key + ".type", "missing (perspective or orthographic)");
    const std::string t = r.string(*type, key + ".type");
    if (t == "orthographic") {
        camera.perspective = false;
        return camera;
    }
    if (t != "perspective")
        r.fail(key + ".type",
               "unknown camera type '" + quoteText(t) + "' (allowed: perspective, orthographic)");
    const std::string pkey = key + ".perspective";
    const json* p = ViewReader::find(c, "perspective");
    if (!p) r.fail(pkey, "missing (a perspective camera needs yfov and znear)");
    r.object(*p, pkey);
    const json* yfov = ViewReader::find(*p, "yfov");
    const json* znear = ViewReader::find(*p, "znear");
    if (!yfov) r.fail(pkey + ".yfov", "missing");
    if (!znear) r.fail(pkey + ".znear", "missing");
    camera.yfov = r.number(*yfov, pkey + ".yfov");
    if (!(camera.yfov > 0.0 && camera.yfov < std::numbers::pi))
        r.fail(pkey + ".yfov", "must be in (0, pi) radians");
    camera.znear = r.number(*znear, pkey + ".znear");
    if (!(camera.znear > 0.0)) r.fail(pkey + ".znear", "must be > 0");
    if (const json* zfar = ViewReader::find(*p, "zfar")) {
        camera.zfar = r.number(*zfar, pkey + ".zfar");
        if (!(*camera.zfar > camera.znear)) r.fail(pkey + ".zfar", "must be greater than znear");
    }
    if (const json* aspect = ViewReader::find(*p, "aspectRatio"))
        if (!(r.number(*aspect, pkey + ".aspectRatio") > 0.0))
            r.fail(pkey + ".aspectRatio", "must be > 0");
    return camera;
}

GltfPunctualLight readLight(const ViewReader& r, const json& l, const std::string& key) {
    r.object(l, key);
    GltfPunctualLight light;
    light.name = r.optName(l, key);
    const json* type = ViewReader::find(l, "type");
    if (!type) r.fail(key + ".type", "missing (point, spot or directional)");
    light.type = r.string(*type, key + ".type");
    if (light.type != "point" && light.type != "spot" && light.type != "directional")
        r.fail(key + ".type", "unknown light type '" + quoteText(light.type) +
                                  "' (allowed: point, spot, directional)");
    if (const json* color = ViewReader::find(l, "color")) {
        const std::vector<double> rgb = r.at(*color, key + ".color").numbers(3);
        for (int i = 0; i < 3; ++i) {
            light.color[i] = rgb[static_cast<std::size_t>(i)];
            if (light.color[i] < 0.0) r.fail(key + ".color", "must be >= 0");
        }
    }
    if (const json* intensity = ViewReader::find(l, "intensity")) {
        light.intensity = r.number(*intensity, key + ".intensity");
        if (light.intensity < 0.0) r.fail(key + ".intensity", "must be >= 0");
    }
    if (const json* range = ViewReader::find(l, "range"))
        if (!(r.number(*range, key + ".range") > 0.0)) r.fail(key + ".range", "must be > 0");
    const json* spot = ViewReader::find(l, "spot");
    if (light.type == "spot" && !spot) r.fail(key + ".spot", "missing (a spot light needs it)");
    if (spot) {
        const std::string skey = key + ".spot";
        r.object(*spot, skey);
        double inner = 0.0, outer = std::numbers::pi / 4.0;
        if (const json* v = ViewReader::find(*spot, "innerConeAngle"))
            inner = r.number(*v, skey + ".innerConeAngle");
        if (const json* v = ViewReader::find(*spot, "outerConeAngle"))
            outer = r.number(*v, skey + ".outerConeAngle");
        if (!(inner >= 0.0 && inner < outer && outer <= std::numbers::pi / 2.0))
            r.fail(skey, "cone angles must satisfy 0 <= innerConeAngle < outerConeAngle <= pi/2");
    }
    return light;
}

// The KHR_lights_punctual lights array of the document, or nullptr.
const json* punctualLights(const ViewReader& r, const json& root) {
    const json* extensions = ViewReader::find(root, "extensions");
    if (!extensions) return nullptr;
    r.object(*extensions, "extensions");
    const json* khr = ViewReader::find(*extensions, "KHR_lights_punctual");
    if (!khr) return nullptr;
    r.object(*khr, "extensions.KHR_lights_punctual");
    const json* lights = ViewReader::find(*khr, "lights");
    if (!lights) return nullptr;
    return &r.array(*lights, "extensions.KHR_lights_punctual.lights");
}

// The light a node places (its KHR_lights_punctual.light), or -1.
int nodeLight(const ViewReader& r, const json& node, const std::string& key, std::size_t count) {
    const json* extensions = ViewReader::find(node, "extensions");
    if (!extensions) return -1;
    r.object(*extensions, key + ".extensions");
    const json* khr = ViewReader::find(*extensions, "KHR_lights_punctual");
    if (!khr) return -1;
    const std::string kkey = key + ".extensions.KHR_lights_punctual";
    r.object(*khr, kkey);
    const json* light = ViewReader::find(*khr, "light");
    if (!light) r.fail(kkey + ".light", "missing");
    return r.reference(*light, kkey + ".light", count, "light");
}

}  // namespace

void readCamerasAndLights(const json& root, GltfDocument& doc) {
    const ViewReader r(doc);
    if (const json* cameras = ViewReader::find(root, "cameras")) {
        r.array(*cameras, "cameras");
        for (std::size_t i = 0; i < cameras->size(); ++i)
            doc.cameras.push_back(readCamera(r, (*cameras)[i], "cameras." + std::to_string(i)));
    }
    if (const json* lights = punctualLights(r, root))
        for (std::size_t i = 0; i < lights->size(); ++i)
            doc.lights.push_back(readLight(
                r, (*lights)[i], "extensions.KHR_lights_punctual.lights." + std::to_string(i)));
    const json* nodes = ViewReader::find(root, "nodes");
    if (!nodes) return;  // checkGltfJson checked its type
    for (std::size_t n = 0; n < nodes->size(); ++n) {
        const json& node = (*nodes)[n];
        const std::string key = "nodes." + std::to_string(n);
        int camera = -1;
        if (const json* c = ViewReader::find(node, "camera"))
            camera = r.reference(*c, key + ".camera", doc.cameras.size(), "camera");
        doc.node_camera.push_back(camera);
        doc.node_light.push_back(nodeLight(r, node, key, doc.lights.size()));
    }
}

}  // namespace penumbra::scene
