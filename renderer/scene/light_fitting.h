// Greedy fitting of uniform area lights to an environment map (Annen et al. 2008, 4.2): on
// each cube face, a light grows from the brightest uncovered texel while each enlargement
// adds more than a threshold share of the enlarged light's energy; its energy is then taken
// from the face, leaving a residual, until the faces are covered or enough lights are fitted.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "renderer/scene/cube_faces.h"

namespace penumbra::scene {

struct FitSettings {
    double threshold = 0.1;  // t: enlarge while E_added / E_enlarged > t
    int max_lights = 0;      // 0: until every texel is covered
    bool square = false;     // square lights (the paper's choice) instead of rectangles
    double residual = 0.0;   // share of the face's mean energy left in each covered texel
};

struct FittedLight {
    int face = 0;
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;  // texel rectangle [x0, x1) x [y0, y1) on the face
    glm::vec3 direction{0.0f};           // unit direction of the rectangle's centre
    glm::vec3 right{0.0f}, up{0.0f};     // unit axes of the light, perpendicular to direction
    glm::vec2 extent{0.0f};              // full angular width and height, radians
    double solid_angle = 0;              // of the rectangle, steradians
    glm::vec3 energy{0.0f};              // RGB radiance x solid angle captured
    glm::vec3 radiance() const { return energy / static_cast<float>(solid_angle); }
    double share = 0;  // of the map's luminance energy
};

struct LightFit {
    std::vector<FittedLight> lights;  // in fitting order (brightest seed first)
    double total = 0;                 // the map's luminance energy
    double captured = 0;              // share of it carried by the lights
};

// Fits lights to FACES with SETTINGS. Seeds are taken across all faces brightest first, so
// with max_lights the brightest parts of the whole map are fitted first.
LightFit fitLights(const CubeFaces& faces, const FitSettings& settings);

// {"schema": "penumbra-lights", ...}: settings, totals and every light (face, texels,
// direction, right, up, extent in degrees, solid angle, radiance, energy share).
nlohmann::json lightFitJson(const LightFit& fit, const FitSettings& settings, int face_size);
// Reads lightFitJson's output back; throws InputError naming WHERE and the key at fault.
LightFit lightFitFromJson(const nlohmann::json& j, const std::string& where);

}  // namespace penumbra::scene
