// Rect lights that stand for a scene's environment map: the lights `css` fits to it (section
// 4.2 of Annen et al. 2008) and the many small lights, sampled by energy, that the environment
// reference renders with one hard shadow map each. Both are placed far outside the scene.
#pragma once

#include "renderer/core/params.h"
#include "renderer/scene/light_fitting.h"
#include "renderer/techniques/technique.h"

namespace penumbra::techniques {

// Light K of a fit as a rect light: at distance 10 x the camera's far plane from the origin,
// facing it, sized to the fitted angular extent, carrying the light's energy; the map turned by
// the environment's rotation_y.
scene::RectLight farLight(const scene::Scene& s, const scene::FittedLight& light);

// `css`: fits lights to S's environment with P's env_threshold, env_lights, env_shape and
// env_face_size, or reads them from env_lights_file (the first env_lights of them).
EnvironmentLights fittedEnvironmentLights(const Params& p, const scene::Scene& s);
// `reference`: P's env_samples directions drawn by luminance energy from the cube faces (stratified
// in the energy's cumulative distribution), each a small light carrying an equal share.
EnvironmentLights sampledEnvironmentLights(const Params& p, const scene::Scene& s);

}  // namespace penumbra::techniques
