#version 450 core
// Adds a batch of lights' shading terms (passes/shading.glsl, lightIrradiance: rgb the shadowed
// irradiance, a the unshadowed luminance irradiance) from their visibility layers to the
// environment's irradiance sum (additive blending): the lights a technique makes of an
// environment, folded a batch at a time into the layer `exact` fills, instead of a layer each.
#include "common/bindings.glsl"
#include "passes/shading.glsl"

layout(binding = UNIT_SHADE_POSITION) uniform sampler2D u_position;
layout(binding = UNIT_SHADE_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_SHADE_ID) uniform isampler2D u_id;
uniform int u_light;  // the batch's first light, index into u_lights
uniform int u_layer;  // its layer of u_visibility; light u_light + i is in layer u_layer + i
uniform int u_count;  // lights in the batch

layout(location = 0) out vec4 o_irradiance;

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(u_position, pix, 0);
    if (pos.w == 0.0) discard;
    vec3 n = normalize(texelFetch(u_normal, pix, 0).xyz);
    bool casts = objectCasts(texelFetch(u_id, pix, 0).r);
    vec3 g = geometricNormal(pix);
    vec4 sum = vec4(0.0);
    for (int i = 0; i < u_count; ++i) {
        vec4 layer = texelFetch(u_visibility, ivec3(pix, u_layer + i), 0);
        sum += lightIrradiance(u_lights[u_light + i], layer, pos.xyz, n, g, casts);
    }
    o_irradiance = sum;
}
