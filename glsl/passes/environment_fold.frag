#version 450 core
// Adds one light's shading term (passes/shading.glsl, lightIrradiance: rgb its shadowed
// irradiance, a its unshadowed luminance irradiance) from its visibility layer to the
// environment's irradiance sum (additive blending): the lights a technique makes of an
// environment, folded one at a time into the layer `exact` fills, instead of a layer each.
#include "common/bindings.glsl"
#include "passes/shading.glsl"

layout(binding = UNIT_SHADE_POSITION) uniform sampler2D u_position;
layout(binding = UNIT_SHADE_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_SHADE_ID) uniform isampler2D u_id;
uniform int u_light;  // index into u_lights
uniform int u_layer;  // its layer of u_visibility

layout(location = 0) out vec4 o_irradiance;

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(u_position, pix, 0);
    if (pos.w == 0.0) discard;
    vec3 n = normalize(texelFetch(u_normal, pix, 0).xyz);
    bool casts = objectCasts(texelFetch(u_id, pix, 0).r);
    vec4 layer = texelFetch(u_visibility, ivec3(pix, u_layer), 0);
    o_irradiance =
        lightIrradiance(u_lights[u_light], layer, pos.xyz, n, geometricNormal(pix), casts);
}
