#version 450 core
// Beauty = albedo/pi * sum_i L_i E_i V_i, with E_i the exact unshadowed irradiance from rect
// light i (polygon form factor clipped to the horizon), and the irradiance-weighted visibility
// sum(E_i V_i) / sum(E_i) (luminance of L_i E_i as the weight).
#include "common/bindings.glsl"
#include "common/light_irradiance.glsl"

struct GpuLight {
    vec4 corners[4];
    vec4 forward;
    vec4 radiance;  // rgb, w = luminance
};
layout(std430, binding = BINDING_LIGHTS) readonly buffer Lights { GpuLight u_lights[]; };

in vec2 v_uv;
layout(binding = 0) uniform sampler2D u_position;
layout(binding = 1) uniform sampler2D u_normal;
layout(binding = 2) uniform sampler2D u_albedo;
layout(binding = 3) uniform sampler2DArray u_visibility;
uniform int u_light_count;

layout(location = 0) out vec4 o_beauty;
layout(location = 1) out vec4 o_visibility;

const float kPi = 3.14159265358979;

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(u_position, pix, 0);
    if (pos.w == 0.0) {
        o_beauty = vec4(0.0);
        o_visibility = vec4(1.0, 0.0, 0.0, 0.0);
        return;
    }
    vec3 n = normalize(texelFetch(u_normal, pix, 0).xyz);
    vec3 albedo = texelFetch(u_albedo, pix, 0).rgb;
    vec3 radiance = vec3(0.0);
    float num = 0.0, den = 0.0, plain = 0.0;
    for (int i = 0; i < u_light_count; ++i) {
        GpuLight l = u_lights[i];
        vec3 c[4] = vec3[4](l.corners[0].xyz, l.corners[1].xyz, l.corners[2].xyz, l.corners[3].xyz);
        float e = rectLightIrradiance(c, l.forward.xyz, pos.xyz, n);
        float v = texelFetch(u_visibility, ivec3(pix, i), 0).r;
        radiance += albedo / kPi * l.radiance.rgb * e * v;
        num += l.radiance.w * e * v;
        den += l.radiance.w * e;
        plain += v;
    }
    o_beauty = vec4(radiance, 1.0);
    // Where no light reaches the point unshadowed, fall back to the plain mean.
    float vis = den > 0.0 ? num / den : plain / float(max(u_light_count, 1));
    o_visibility = vec4(clamp(vis, 0.0, 1.0), 0.0, 0.0, 0.0);
}
