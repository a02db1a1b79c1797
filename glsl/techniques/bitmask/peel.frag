#version 450 core
// `bitmask` with layers 2: the far layer's level 0, per texel the distance of the nearest
// caster surface more than u_peel_gap (relative) beyond the front map's, as (min, max) like the
// HSM's level 0: a sphere's far side, which the light's edges see under its silhouette. IDS 1:
// the texel's owner in colour 1, as glsl/passes/light_depth.frag's.
#include "techniques/bitmask/bindings.glsl"
in float v_depth;  // the distance (the view's near 0, range 1)
layout(binding = BITMASK_UNIT_PEEL_FRONT) uniform sampler2D u_front;  // HSM level 0
uniform float u_peel_gap;
layout(location = 0) out vec2 o_range;
#ifndef IDS
#define IDS 0
#endif
#if IDS
uniform int u_object_id;
layout(location = 1) out vec2 o_owner;
#endif

void main() {
    float front = texelFetch(u_front, ivec2(gl_FragCoord.xy), 0).r;
    if (v_depth <= front * (1.0 + u_peel_gap)) discard;
    o_range = vec2(v_depth);
#if IDS
    o_owner = vec2(float(u_object_id), 1e30);
#endif
}
