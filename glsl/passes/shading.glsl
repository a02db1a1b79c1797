// Shading of one G-buffer point by every light (include-only, shared by shade.frag and
// shade_samples.frag): beauty = albedo/pi * sum_i L_i E_i V_i with E_i the exact unshadowed
// irradiance of rect light i, and the irradiance-weighted visibility sum(E_i V_i) / sum(E_i).
#ifndef PENUMBRA_SHADING_GLSL
#define PENUMBRA_SHADING_GLSL

#include "common/bindings.glsl"
#include "common/light_irradiance.glsl"

struct GpuLight {
    vec4 corners[4];
    vec4 forward;
    vec4 radiance;  // rgb, w = luminance
};
layout(std430, binding = BINDING_LIGHTS) readonly buffer Lights { GpuLight u_lights[]; };

layout(binding = 3) uniform sampler2DArray u_visibility;  // one layer per light
uniform int u_light_count;

const float kPi = 3.14159265358979;

// Radiance leaving POS (unit normal N, linear ALBEDO) lit by every light, with the visibility
// layers of pixel VIS_PIX (fully visible where VIS_PIX.x < 0); VISIBILITY gets the
// irradiance-weighted visibility (the plain mean where no light reaches the point unshadowed).
vec3 shadePoint(vec3 pos, vec3 n, vec3 albedo, ivec2 vis_pix, out float visibility) {
    vec3 radiance = vec3(0.0);
    float num = 0.0, den = 0.0, plain = 0.0;
    for (int i = 0; i < u_light_count; ++i) {
        GpuLight l = u_lights[i];
        vec3 c[4] = vec3[4](l.corners[0].xyz, l.corners[1].xyz, l.corners[2].xyz, l.corners[3].xyz);
        float e = rectLightIrradiance(c, l.forward.xyz, pos, n);
        float v = vis_pix.x < 0 ? 1.0 : texelFetch(u_visibility, ivec3(vis_pix, i), 0).r;
        radiance += albedo / kPi * l.radiance.rgb * e * v;
        num += l.radiance.w * e * v;
        den += l.radiance.w * e;
        plain += v;
    }
    visibility = clamp(den > 0.0 ? num / den : plain / float(max(u_light_count, 1)), 0.0, 1.0);
    return radiance;
}

#endif  // PENUMBRA_SHADING_GLSL
