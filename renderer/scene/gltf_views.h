// A glTF file's cameras and KHR_lights_punctual lights as read and checked (gltf_views.cpp), and
// where its node hierarchy places them: what a scene takes from a glTF besides its meshes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace penumbra::scene {

// One entry of the glTF's `cameras`, checked (gltf_views.cpp).
struct GltfCamera {
    std::string name;
    bool perspective = true;     // false: orthographic (kept to be refused by name)
    double yfov = 0.0;           // radians, in (0, pi)
    double znear = 0.0;          // > 0
    std::optional<double> zfar;  // > znear; absent: infinite
};

// One entry of KHR_lights_punctual's `lights`, checked (gltf_views.cpp).
struct GltfPunctualLight {
    std::string name;
    std::string type;        // "point", "spot" or "directional"
    glm::dvec3 color{1.0};   // linear RGB, each >= 0
    double intensity = 1.0;  // candela (point, spot) or lux (directional), >= 0
};

// A camera or light placed by a node of the glTF scene.
struct GltfPlacement {
    int index;         // into the cameras or lights
    int node;          // the node that places it
    glm::dmat4 world;  // the node's world transform (glTF scene space)
};

}  // namespace penumbra::scene
