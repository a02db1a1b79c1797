#version 450 core
// `ssm` with far_side=second: the far side's occluder map holds, per texel, the nearest caster
// surface at least u_peel_gap (normalised depth) beyond the front map's: a box's walls hidden
// from the light's centre, where the farthest surface would be the floor the box rests on.
#include "techniques/ssm/bindings.glsl"
in float v_depth;
in vec3 v_world;
in vec3 v_normal;
layout(binding = SSM_UNIT_OCC_PEEL_FRONT) uniform sampler2D u_front;  // the front map's depth
uniform float u_peel_gap;
#include "common/light_frame.glsl"
uniform int u_object_id;
layout(location = 0) out int o_id;

void main() {
    float d = clamp(v_depth, 0.0, 1.0);
    if (d <= texelFetch(u_front, ivec2(gl_FragCoord.xy), 0).r + u_peel_gap) discard;
    gl_FragDepth = d;
    o_id = u_object_id;
}
