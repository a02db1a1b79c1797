#version 450 core
// `ssm` receiver layers in one pass: each receiver fragment that faces the light's centre goes
// into its texel's k-buffer, sorted nearest slots (an atomic-min cascade) and the farthest.
#include "techniques/ssm/bindings.glsl"
in float v_depth;
in vec3 v_world;
in vec3 v_normal;
#include "common/light_frame.glsl"
uniform int u_object_id;
uniform int u_closed;  // 1: the object's model is a closed surface (GpuModel::closed)
uniform int u_nearest_slots;  // slots 0 .. u_nearest_slots - 1, ascending; then the farthest
uniform bool u_farthest;      // keep the farthest fragment (layers > 1)
// Cleared to 0xffffffff (the nearest slots) and 0 (the farthest)
layout(binding = SSM_IMAGE_KBUFFER, r32ui) uniform coherent uimage2DArray u_slots;

const uint kEmpty = 0xffffffffu;
const uint kIdMask = (1u << SSM_KBUFFER_ID_BITS) - 1u;

void main() {
    // A solid's face turned away from the light's centre lies behind one turned towards it; an
    // open sheet's is the side the light sees (a card whose stored normal faces away: mix9200).
    if (u_closed != 0 && dot(v_normal, u_light_centre - v_world) <= 0.0) return;
    uint q = uint(round(clamp(v_depth, 0.0, 1.0) * float(SSM_KBUFFER_DEPTH_STEPS)));
    uint id = uint(u_object_id);
    ivec2 p = ivec2(gl_FragCoord.xy);
    // Slots only fall (the nearest) or rise (the farthest): a fragment that a plain load shows
    // cannot enter skips the atomics (most fragments of a deep stack). The farthest keeps the
    // first object at equal depths (the inverted id), as the peeling's greater test did.
    uint far_value = (q << SSM_KBUFFER_ID_BITS) | (kIdMask - id);
    if (u_farthest && far_value > imageLoad(u_slots, ivec3(p, u_nearest_slots)).r)
        imageAtomicMax(u_slots, ivec3(p, u_nearest_slots), far_value);
    // The peeling's less test against the cleared 1 kept no surface at depth 1.
    if (q >= uint(SSM_KBUFFER_DEPTH_STEPS)) return;
    // Insertion: each slot keeps the smaller value and the larger moves on to the next one.
    uint v = (q << SSM_KBUFFER_ID_BITS) | id;
    if (v >= imageLoad(u_slots, ivec3(p, u_nearest_slots - 1)).r) return;
    for (int i = 0; i < u_nearest_slots; ++i) {
        uint old = imageAtomicMin(u_slots, ivec3(p, i), v);
        if (old == kEmpty) return;
        v = max(old, v);
    }
}
