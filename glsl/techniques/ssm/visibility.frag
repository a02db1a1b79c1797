#version 450 core
// `ssm` visibility: each camera pixel of a receiver is projected from the light's centre into
// the soft shadow map (two maps merged by max when two-sided, 3.5); visibility = 1 - occlusion.
// Pixels of objects that receive no shadow are lit. Diagnostic 0: the raw summed occlusion.
#ifndef TWO_SIDED
#define TWO_SIDED 0
#endif
in vec2 v_uv;
layout(binding = 0) uniform sampler2D u_position;
layout(binding = 1) uniform isampler2D u_id;
layout(binding = 2) uniform sampler2D u_receives;  // 1 per object id that receives shadows
layout(binding = 3) uniform sampler2D u_ssm;
#if TWO_SIDED
layout(binding = 4) uniform sampler2D u_ssm_back;
#endif
uniform vec3 u_light_centre;
uniform vec3 u_light_right;
uniform vec3 u_light_up;
uniform vec3 u_light_forward;
uniform vec2 u_ssm_lo;
uniform vec2 u_ssm_size;
uniform int u_shadowed;  // 0: no occluder lies between the light and a receiver

layout(location = 0) out vec4 o_visibility;
layout(location = 1) out vec4 o_occlusion;

void main() {
    ivec2 pix = ivec2(gl_FragCoord.xy);
    vec4 pos = texelFetch(u_position, pix, 0);
    if (pos.w == 0.0) discard;
    o_visibility = vec4(1.0, 0.0, 0.0, 0.0);
    o_occlusion = vec4(0.0);
    int id = texelFetch(u_id, pix, 0).r;
    if (u_shadowed == 0 || id < 0 || texelFetch(u_receives, ivec2(id, 0), 0).r < 0.5) return;
    vec3 d = pos.xyz - u_light_centre;
    float z = dot(d, u_light_forward);
    if (z <= 0.0) return;
    vec2 uv = (vec2(dot(d, u_light_right), dot(d, u_light_up)) / z - u_ssm_lo) / u_ssm_size;
    if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0)))) return;
    float occlusion = texture(u_ssm, uv).r;
#if TWO_SIDED
    occlusion = max(occlusion, texture(u_ssm_back, uv).r);
#endif
    o_visibility = vec4(1.0 - clamp(occlusion, 0.0, 1.0), 0.0, 0.0, 0.0);
    o_occlusion = vec4(occlusion, 0.0, 0.0, 0.0);
}
