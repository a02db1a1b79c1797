#version 450 core
// The shade pass, one sample per pixel: every pixel's G-buffer point shaded with its own
// visibility layers (passes/shading.glsl).
#include "common/bindings.glsl"
#include "passes/shading.glsl"

in vec2 v_uv;
layout(binding = UNIT_SHADE_POSITION) uniform sampler2D u_position;
layout(binding = UNIT_SHADE_NORMAL) uniform sampler2D u_normal;
layout(binding = UNIT_SHADE_ALBEDO) uniform sampler2D u_albedo;
layout(binding = UNIT_SHADE_ID) uniform isampler2D u_id;  // -1: background

layout(location = 0) out vec4 o_beauty;      // rgb, a = coverage
layout(location = 1) out vec4 o_visibility;

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
    float vis;
    o_beauty = vec4(shadePoint(pos.xyz, n, albedo, texelFetch(u_id, pix, 0).r, pix, vis), 1.0);
    o_visibility = vec4(vis, 0.0, 0.0, 0.0);
}
