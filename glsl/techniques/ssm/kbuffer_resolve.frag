#version 450 core
// `ssm` receiver layers from the k-buffer (kbuffer_insert.frag): walks a texel's sorted slots as
// the peeling did (each layer more than u_peel_gap beyond the one before, the last the farthest
// beyond that) and writes layer u_layer's depth (1 where none) and object id (-1 where none).
#include "techniques/ssm/bindings.glsl"
layout(binding = SSM_IMAGE_KBUFFER, r32ui) uniform readonly uimage2DArray u_slots;
uniform int u_layer;
uniform int u_layers;
uniform int u_nearest_slots;
uniform float u_peel_gap;
layout(std430, binding = SSM_BINDING_LAYER_COUNTS) buffer LayerCounts {
    uint used;      // the most layers a texel holds
    uint overflow;  // texels whose nearest slots filled up before their layers were found
};
in vec2 v_uv;
layout(location = 0) out int o_id;

const uint kEmpty = 0xffffffffu;
const uint kIdMask = (1u << SSM_KBUFFER_ID_BITS) - 1u;

float depthOf(uint v) {
    return float(v >> SSM_KBUFFER_ID_BITS) / float(SSM_KBUFFER_DEPTH_STEPS);
}

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int walk = max(u_layers - 1, 1);  // the layers the nearest slots give
    float depth = 1.0, last = 0.0;
    int id = -1, found = 0, i = 0;
    for (; i < u_nearest_slots && found < walk; ++i) {
        uint v = imageLoad(u_slots, ivec3(p, i)).r;
        if (v == kEmpty) break;
        float d = depthOf(v);
        if (found > 0 && d <= last + u_peel_gap) continue;  // within the gap of the layer before
        if (found == u_layer) depth = d, id = int(v & kIdMask);
        last = d;
        ++found;
    }
    bool overflowed = found < walk && i == u_nearest_slots;
    if (u_layers > 1 && found == walk) {
        uint v = imageLoad(u_slots, ivec3(p, u_nearest_slots)).r;
        float d = depthOf(v);
        if (v != 0u && d > last + u_peel_gap) {
            if (found == u_layer) depth = d, id = int(kIdMask - (v & kIdMask));
            ++found;
        }
    }
    if (u_layer == 0) {
        if (found > 0) atomicMax(used, uint(found));
        if (overflowed) atomicAdd(overflow, 1u);
    }
    gl_FragDepth = depth;
    o_id = id;
}
