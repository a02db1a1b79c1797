#version 450 core
// `ssm` receiver layers (depth peeling from the light's centre): keeps the receiver surfaces
// that face the light's centre, and in layer k > 0 only those at least u_peel_gap (normalised
// depth) beyond layer k - 1 at the same texel.
#include "techniques/ssm/bindings.glsl"
in float v_depth;
in vec3 v_world;
in vec3 v_normal;
// The layers peeled so far
layout(binding = SSM_UNIT_PEEL_PREVIOUS) uniform sampler2DArray u_previous;
uniform int u_layer;
uniform float u_peel_gap;
#include "common/light_frame.glsl"
uniform int u_object_id;
uniform int u_closed;  // 1: the object's model is a closed surface (GpuModel::closed)
layout(location = 0) out int o_id;

void main() {
    // A solid's face turned away from the light's centre lies behind one turned towards it; an
    // open sheet's is the side the light sees (a card whose stored normal faces away: mix9200).
    if (u_closed != 0 && dot(v_normal, u_light_centre - v_world) <= 0.0) discard;
    float d = clamp(v_depth, 0.0, 1.0);
    if (u_layer > 0) {
        float before = texelFetch(u_previous, ivec3(ivec2(gl_FragCoord.xy), u_layer - 1), 0).r;
        if (before >= 1.0 || d <= before + u_peel_gap) discard;
    }
    gl_FragDepth = d;
    o_id = u_object_id;
}
