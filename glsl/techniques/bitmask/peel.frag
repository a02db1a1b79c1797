#version 450 core
// `bitmask` with layers 2: the far layer's level 0, per texel the distance of the nearest
// caster surface more than u_peel_gap (relative) beyond the front map's, as (min, max) like the
// HSM's level 0: a sphere's far side, which the light's edges see under its silhouette. IDS 1:
// the texel's owner in colour 1, as glsl/passes/light_depth.frag's, and with u_others_first
// (`peel` others_first) another object's surface wins over the far side of the front texel's own
// object, whatever their order: a closed caster between the light and a ball held its own far
// side in this layer and the ball in none, so the floor under the ball was lit where `exact` has
// it in umbra (random scene rand9803).
#include "techniques/bitmask/bindings.glsl"
in float v_depth;  // the distance (the view's near 0, range 1)
layout(binding = BITMASK_UNIT_PEEL_FRONT) uniform sampler2D u_front;  // HSM level 0
uniform float u_peel_gap;
uniform int u_others_first;  // 1: another object before the front texel's own (IDS 1)
layout(location = 0) out vec2 o_range;
#ifndef IDS
#define IDS 0
#endif
#if IDS
uniform int u_object_id;
layout(location = 1) out vec2 o_owner;
// The front map's owners (HSM level 0): (object id, ...), -1 where no caster is
layout(binding = BITMASK_UNIT_PEEL_FRONT_OWNERS) uniform sampler2D u_front_owners;
#endif

void main() {
    float front = texelFetch(u_front, ivec2(gl_FragCoord.xy), 0).r;
    if (v_depth <= front * (1.0 + u_peel_gap)) discard;
    o_range = vec2(v_depth);
#if IDS
    o_owner = vec2(float(u_object_id), 1e30);
    // Depth: another object's in [0, 0.5), the front object's own in [0.5, 1), each by distance.
    bool own = u_others_first == 1 &&
               int(texelFetch(u_front_owners, ivec2(gl_FragCoord.xy), 0).r) == u_object_id;
    float ranked = 0.5 * (v_depth / (1.0 + v_depth)) + (own ? 0.5 : 0.0);
    gl_FragDepth = u_others_first == 1 ? ranked : gl_FragCoord.z;
#endif
}
