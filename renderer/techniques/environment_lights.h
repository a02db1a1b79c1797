// Rect lights that stand for a scene's environment map: the lights `css` fits to it (section
// 4.2 of Annen et al. 2008) and the many small lights, sampled by energy, that the environment
// reference renders with one hard shadow map each. Both are placed far outside the scene.
#pragma once

#include <array>

#include "renderer/core/params.h"
#include "renderer/scene/light_fitting.h"
#include "renderer/techniques/param_keys.h"
#include "renderer/techniques/technique.h"

namespace penumbra::techniques {

enum class EnvShape { Square, Rect };
inline constexpr EnumKey<EnvShape, 2> kEnvShape{"env_shape", {"square", "rect"}};

inline constexpr FloatKey kEnvThreshold{"env_threshold"};
inline constexpr IntKey kEnvLights{"env_lights"};
inline constexpr IntKey kEnvFaceSize{"env_face_size"};
inline constexpr TextKey kEnvLightsFile{"env_lights_file"};

// The rows fittedEnvironmentLights reads; `css` ends its table with them.
inline constexpr std::array kFittedEnvironmentParams = {
    floatParam(kEnvThreshold, 0.1, 0.001, 0.999,
               "environment: fitting threshold t (enlarge while E_added / E_enlarged > t)"),
    intParam(kEnvLights, 30, 1, 1024, "environment: the most lights fitted (brightest first)"),
    enumParam(kEnvShape, EnvShape::Square, "environment: shape of the fitted lights"),
    intParam(kEnvFaceSize, 32, 4, 256, "environment: cube face resolution for the fitting"),
    stringParam(kEnvLightsFile, "",
                "environment: lights from a `penumbra fit-lights` JSON (relative to the scene "
                "file) instead of fitting; empty = fit"),
};

// The row sampledEnvironmentLights reads besides the technique's `seed`; `reference` ends its
// table with it.
inline constexpr std::array kSampledEnvironmentParams = {
    intParam(kEnvSamples, 512, 1, 1024,
             "environment: directions sampled by energy, one hard shadow map each"),
};

// Light K of a fit as a rect light: at distance 10 x the camera's far plane from the origin,
// facing it, sized to the fitted angular extent, carrying the light's energy; the map turned by
// the environment's rotation_y.
scene::RectLight farLight(const scene::Scene& s, const scene::FittedLight& light);

// `css`: fits lights to S's environment with P's env_threshold, env_lights, env_shape and
// env_face_size, or reads them from env_lights_file (the first env_lights of them).
EnvironmentLights fittedEnvironmentLights(const Params& p, const scene::Scene& s);
// `reference`: P's env_samples directions drawn by luminance energy from the cube faces (stratified
// in the energy's cumulative distribution), each a small light carrying an equal share; folded
// a batch at a time into the environment's irradiance layer (EnvironmentLights::fold).
EnvironmentLights sampledEnvironmentLights(const Params& p, const scene::Scene& s);
// The most lights each makes (TechniqueInfo::environment_lights_max).
int fittedEnvironmentLightsMax(const Params& p);
int sampledEnvironmentLightsMax(const Params& p);

}  // namespace penumbra::techniques
